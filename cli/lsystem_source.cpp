#include "cli/lsystem_source.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>

#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "lsystem/parser.hpp"

namespace fspm::cli {

bool is_mesh_path(const std::string& path) {
  const std::optional<MeshFormat> format = written_mesh_format(file_kind_by_extension(path));
  return format.has_value() && *format != MeshFormat::kPvd;
}

bool is_ctree_path(const std::string& path) {
  return file_kind_by_extension(path) == FileKind::kCtree;
}

bool is_lsystem_path(const std::string& path) {
  return file_kind_by_extension(path) == FileKind::kLsystem;
}

void add_lsystem_draw_options(CLI::App* command, LsystemDrawArguments& arguments) {
  command->add_flag("--compressed", arguments.compressed,
                    "L-system: derive into shared substructures and draw each once, placed by "
                    "rigid transforms (Jaeger 3.1.2); plants far too large to derive explicitly");
  command
      ->add_option("--variants", arguments.variants,
                   "L-system with --compressed: stochastic productions derived with K variants "
                   "per substructure (Jaeger 2.1.3)")
      ->check(number_in(1, 1e6));
  command
      ->add_option("--steps", arguments.steps, "L-system: derivation steps (default: the file's)")
      ->check(number_in(0, lsystem::kMaxDerivationLength));
}

void check_lsystem_draw_arguments(const LsystemDrawArguments& arguments,
                                  const std::vector<std::string>& files) {
  if (!arguments.given()) return;
  if (std::none_of(files.begin(), files.end(), is_lsystem_path)) {
    throw ValueError("--compressed, --steps and --variants apply to L-system files (.l)",
                     files.empty() ? std::string() : files.front());
  }
}

LsystemSource lsystem_draw_source(const std::string& file, const LsystemDrawArguments& arguments) {
  check_lsystem_draw_arguments(arguments, {file});
  LsystemSource source;
  source.file = file;
  source.steps = arguments.steps;
  source.variants = arguments.variants;
  return source;
}

}  // namespace fspm::cli
