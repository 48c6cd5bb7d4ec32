#include "fspm/tree_file.hpp"

#include <filesystem>
#include <iterator>

#include "fspm/atomic_file.hpp"
#include "fspm/binary_tree_format.hpp"
#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/finite_geometry.hpp"
#include "fspm/input_file.hpp"
#include "fspm/mtg_format.hpp"
#include "fspm/newick_format.hpp"
#include "fspm/text_tree_format.hpp"

namespace fspm {

TreeFormat tree_format_for(const std::string& path, std::string_view name) {
  std::string key(name);
  if (key.empty()) key = tree_format_of_kind(file_kind_by_extension(path));
  if (key.empty()) {
    key = std::filesystem::path(path).extension().string();
    if (!key.empty() && key.front() == '.') key.erase(0, 1);
  }
  if (key == "tree" || key == "text") return TreeFormat::kText;
  if (key == "treeb" || key == "binary") return TreeFormat::kBinary;
  if (key == "nwk" || key == "newick") return TreeFormat::kNewick;
  if (key == "mtg") return TreeFormat::kMtg;
  throw ValueError("unknown tree format '" + key +
                       "': expected .tree (text), .treeb (binary), .nwk (Newick) or .mtg",
                   path);
}

std::string_view tree_format_name(TreeFormat format) {
  switch (format) {
    case TreeFormat::kText:
      return "tree";
    case TreeFormat::kBinary:
      return "treeb";
    case TreeFormat::kNewick:
      return "nwk";
    case TreeFormat::kMtg:
      return "mtg";
  }
  return "tree";
}

namespace {

TreeGraph read_tree_stream(std::istream& in, TreeFormat f, const std::string& path) {
  switch (f) {
    case TreeFormat::kText:
      return read_tree_text(in, path);
    case TreeFormat::kBinary:
      return read_tree_binary(in, path);
    default: {
      const std::string text{std::istreambuf_iterator<char>(in), {}};
      return f == TreeFormat::kMtg ? parse_mtg(text, path) : parse_newick(text, path);
    }
  }
}

// A file to read without a format or an extension that names one: the format its first bytes
// tell (fspm/file_kind.hpp), if any.
std::string_view read_format(const std::string& path, std::string_view format) {
  if (!format.empty() || file_kind_by_extension(path) != FileKind::kUnknown) return format;
  return tree_format_of_kind(file_kind(path));
}

}  // namespace

TreeGraph read_tree_file(const std::string& path, std::string_view format,
                         const MtgTreeOptions& mtg) {
  const auto in = open_input_file(path, kMaxTreeFileBytes);
  const TreeFormat f = tree_format_for(path, read_format(path, format));
  if (f != TreeFormat::kMtg) return read_tree_stream(*in, f, path);
  const std::string text{std::istreambuf_iterator<char>(*in), {}};
  return parse_mtg(text, path, mtg);
}

TreeGraph read_tree_file(const std::string& path, std::string_view format) {
  // The path first: a directory or a missing file is not "an unknown format".
  const auto in = open_input_file(path, kMaxTreeFileBytes);
  return read_tree_stream(*in, tree_format_for(path, read_format(path, format)), path);
}

namespace {

void write_tree_format(const TreeGraph& tree, std::span<const std::string> names,
                       const std::string& path, TreeFormat f, std::string_view comment) {
  require_finite_geometry(tree, path);
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        switch (f) {
          case TreeFormat::kText:
            write_tree_text(tree, out, comment);
            break;
          case TreeFormat::kBinary:
            write_tree_binary(tree, out);
            break;
          case TreeFormat::kNewick:
            out << to_newick_named(tree, names) << '\n';
            break;
          case TreeFormat::kMtg:
            write_mtg(tree, out, path);
            break;
        }
      },
      f == TreeFormat::kBinary);
}

}  // namespace

void write_tree_file(const TreeGraph& tree, const std::string& path, std::string_view format) {
  write_tree_format(tree, {}, path, tree_format_for(path, format), {});
}

bool tree_format_keeps_names(TreeFormat format) { return format == TreeFormat::kNewick; }

NamedTree read_named_tree_file(const std::string& path, std::string_view format) {
  const auto in = open_input_file(path, kMaxTreeFileBytes);
  const TreeFormat f = tree_format_for(path, format);
  if (f != TreeFormat::kNewick) return {read_tree_stream(*in, f, path), {}};
  const std::string text{std::istreambuf_iterator<char>(*in), {}};
  return parse_newick_named(text, path);
}

void write_named_tree_file(const NamedTree& named, const std::string& path, std::string_view format,
                           std::string_view comment) {
  const TreeFormat f = tree_format_for(path, format);
  const std::span<const std::string> names =
      tree_format_keeps_names(f) ? named.names : std::span<const std::string>{};
  write_tree_format(named.tree, names, path, f, comment);
}

}  // namespace fspm
