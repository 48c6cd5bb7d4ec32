#include "cli/lsystem_source.hpp"

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>

#include "cli/output.hpp"
#include "fspm/compressed_tree_graph.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_ctree.hpp"
#include "lsystem/instanced_interpretation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/substructure_derivation.hpp"

namespace fspm::cli {

lsystem::MacroOverrides parse_defines(const std::vector<std::string>& defines) {
  lsystem::MacroOverrides out;
  for (const std::string& d : defines) {
    const auto eq = d.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw ValueError("--define expects NAME=VALUE, got '" + d + "'");
    }
    out[d.substr(0, eq)] = d.substr(eq + 1);
  }
  return out;
}

lsystem::DeriveOptions derive_options(const LsystemSource& source) {
  lsystem::DeriveOptions d;
  if (source.steps >= 0) d.steps = source.steps;
  if (source.seed >= 0) d.seed = static_cast<std::uint64_t>(source.seed);
  d.module_budget = source.budget;
  return d;
}

lsystem::LSystem read_lsystem(const LsystemSource& source) {
  return lsystem::parse_lsystem_file(source.file, parse_defines(source.defines));
}

lsystem::TurtleSettings view_settings(const LsystemSource& source) {
  return source.view.empty() ? lsystem::view_for_lsystem(source.file)
                             : lsystem::read_view_file(source.view);
}

namespace {

LsystemDrawing draw_explicitly(const LsystemSource& source, const lsystem::LSystem& sys,
                               const lsystem::TurtleSettings& view) {
  lsystem::DeriveOptions options = derive_options(source);
  options.turtle = &view;
  lsystem::Derivation d(sys, options);
  d.run();
  lsystem::Interpretation drawn = lsystem::interpret(d.interpretation_string(), sys.symbols, view);
  LsystemDrawing out;
  out.summary = {{"steps", d.steps_done()},
                 {"modules", d.string().size()},
                 {"compressed", false},
                 {"nodes", drawn.tree.size()},
                 {"prototypes", 1}};
  out.tree.prototypes.push_back({std::move(drawn.tree), {}});
  out.occurrences = 1;
  return out;
}

LsystemDrawing draw_compressed(const LsystemSource& source, const lsystem::LSystem& sys,
                               const lsystem::TurtleSettings& view, double min_detail, int pixels) {
  const auto t0 = std::chrono::steady_clock::now();
  const lsystem::SubstructureGraph graph =
      lsystem::derive_substructures(sys, derive_options(source), source.variants);
  const double derive_seconds = seconds_since(t0);
  lsystem::InstancedInterpretationOptions options;
  options.module_budget = source.budget;
  // Exact first: the counts of the whole plant, and its size for the level of detail.
  lsystem::InstancedInterpretation exact = lsystem::interpret_instanced(graph, sys, view, options);
  options.min_detail = min_detail;
  if (min_detail < 0.0) {
    const bool sized = pixels > 0 && !exact.bounds.isEmpty();
    options.min_detail = sized ? exact.bounds.sizes().maxCoeff() / pixels : 0.0;
  }
  const bool detailed = options.min_detail > 0.0 && exact.explicit_reason.empty();
  lsystem::InstancedInterpretation drawn =
      detailed ? lsystem::interpret_instanced(graph, sys, view, options) : std::move(exact);
  const lsystem::InstancedInterpretation& whole = detailed ? exact : drawn;
  if (!drawn.explicit_reason.empty()) {
    spdlog::warn("{}: interpreted explicitly, not by instancing, because of {}", source.file,
                 drawn.explicit_reason);
  }
  std::size_t references = 0;
  for (const auto& p : drawn.tree.prototypes) references += p.children.size();
  LsystemDrawing out;
  out.summary = {{"steps", graph.steps},
                 {"compressed", true},
                 {"graph_nodes", graph.nodes.size()},
                 {"graph_bytes", graph.memory_bytes()},
                 {"derive_seconds", derive_seconds},
                 {"prototypes", drawn.tree.prototypes.size()},
                 {"child_references", references},
                 {"instances", count_json(drawn.instances)},
                 {"represented_segments", count_json(whole.internodes)},
                 {"represented_leaves", count_json(whole.leaves)},
                 {"drawn_segments", count_json(drawn.internodes)},
                 {"min_detail", options.min_detail}};
  if (source.variants > 0) out.summary["variants"] = source.variants;
  if (!drawn.explicit_reason.empty()) out.summary["explicit_reason"] = drawn.explicit_reason;
  out.tree = std::move(drawn.tree);
  out.occurrences = drawn.occurrences;
  return out;
}

}  // namespace

LsystemDrawing draw_lsystem(const LsystemSource& source, bool compressed, double min_detail,
                            int pixels) {
  const auto t0 = std::chrono::steady_clock::now();
  const lsystem::LSystem sys = read_lsystem(source);
  const lsystem::TurtleSettings view = view_settings(source);
  LsystemDrawing out;
  const auto obstacle =
      compressed ? lsystem::factorization_obstacle(sys, source.variants > 0) : std::nullopt;
  if (obstacle) {
    const bool variants_would_do =
        source.variants == 0 && !lsystem::factorization_obstacle(sys, true);
    spdlog::warn(
        "{}: derived explicitly, not into substructures: it has {}{}", source.file, *obstacle,
        variants_would_do ? " (--variants K derives it with K variants per substructure)" : "");
  }
  if (compressed && !obstacle) {
    out = draw_compressed(source, sys, view, min_detail, pixels);
  } else {
    out = draw_explicitly(source, sys, view);
    if (obstacle) out.summary["why_not_compressed"] = "it has " + *obstacle;
  }
  out.summary["seconds"] = seconds_since(t0);
  return out;
}

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

bool is_mesh_path(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".obj" || ext == ".ply" || ext == ".vtp" || ext == ".glb";
}

bool is_ctree_path(const std::string& path) { return lower_extension(path) == ".ctree"; }

bool is_lsystem_path(const std::string& path) { return lower_extension(path) == ".l"; }

void write_lsystem_ctree(const LsystemDrawing& drawing, const std::string& path,
                         nlohmann::json& summary) {
  const CompressedTreeGraph graph = compress_instanced_tree(drawing.tree);
  write_ctree_file(graph, path);
  summary["ctree_records"] = graph.size();
  summary["ctree_organs"] = count_json(geometry_organ_count(graph));
  summary["ctree_bytes"] = std::filesystem::file_size(path);
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
