#include "fspm/mtg_format.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <ostream>
#include <vector>

#include "fspm/mtg_reader.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/mtg_writer.hpp"
#include "fspm/number_text.hpp"
#include "fspm/warning.hpp"

namespace fspm {
namespace {

char symbol(OrganKind k) {
  switch (k) {
    case OrganKind::kInternode:
      return 'I';
    case OrganKind::kLeaf:
      return 'L';
    case OrganKind::kFlower:
      return 'F';
    case OrganKind::kBud:
      return 'B';
  }
  return 'I';
}

// The child that continues n's axis ('<' in MTG): the first child of the same order.
NodeId successor(const TreeGraph& t, NodeId n) {
  for (NodeId c : t.children(n)) {
    if (t.order(c) == t.order(n)) return c;
  }
  return kNoNode;
}

// Attributes an MTG import derives from the file's structure: written as structure, not features.
bool derived_from_mtg(const std::string& name) {
  return name == "class" || name == "index" || name == "inferred" || name.ends_with("_index");
}

}  // namespace

void write_mtg(const TreeGraph& tree, std::ostream& out, const std::string& path,
               std::uint64_t max_code_bytes) {
  std::vector<std::string> names = tree.attribute_names();
  std::erase_if(names, derived_from_mtg);
  out << "CODE:\tFORM-A\n\nCLASSES:\nSYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION\n"
         "$\t0\tFREE\tFREE\tIMPLICIT\nP\t1\tFREE\tFREE\tIMPLICIT\n"
         "I\t2\tFREE\tFREE\tIMPLICIT\nL\t2\tFREE\tFREE\tIMPLICIT\n"
         "F\t2\tFREE\tFREE\tIMPLICIT\nB\t2\tFREE\tFREE\tIMPLICIT\n\n"
         "DESCRIPTION:\nLEFT\tRIGHT\tRELTYPE\tMAX\nI\tI,L,F,B\t<\t?\nI\tI,L,F,B\t+\t?\n\n"
         "FEATURES:\nNAME\tTYPE\nXX\tREAL\nYY\tREAL\nZZ\tREAL\nLength\tREAL\nRadius\tREAL\n"
         "BirthTime\tREAL\nOrder\tINT\nOrgan\tALPHA\n";
  for (const std::string& n : names) out << n << "\tREAL\n";
  if (tree.empty()) {
    out << "\nMTG:\nENTITY-CODE\n/P1\n";
    return;
  }

  // Column of each node in the MTG table: branches ('+') move one column to the right.
  // Ids are topologically ordered, so a forward pass suffices.
  std::vector<int> column(tree.size(), 0);
  int columns = 1;
  for (NodeId n = 1; n < tree.size(); ++n) {
    const NodeId p = tree.parent(n);
    column[n] = column[p] + (successor(tree, p) == n ? 0 : 1);
    columns = std::max(columns, column[n] + 1);
  }
  // Every line is padded to the deepest column before its features.
  check_mtg_code_size(
      static_cast<std::uint64_t>(tree.size()) * (static_cast<std::uint64_t>(columns) + 16), columns,
      path, max_code_bytes);
  out << "\nMTG:\nENTITY-CODE";
  for (int c = 0; c < columns; ++c) out << '\t';
  out << "XX\tYY\tZZ\tLength\tRadius\tBirthTime\tOrder\tOrgan";
  for (const std::string& n : names) out << '\t' << n;
  out << "\n/P1\n";

  std::vector<std::span<const double>> attrs;
  for (const std::string& n : names) attrs.push_back(tree.attribute(n));
  std::string line;
  auto emit = [&](NodeId n, const char* relation) {
    line.assign(static_cast<std::size_t>(column[n]), '\t');
    line += relation;
    line += symbol(tree.kind(n));
    line += std::to_string(n + 1);
    line.append(static_cast<std::size_t>(columns - column[n]), '\t');
    const Eigen::Vector3d& e = tree.end(n);
    for (double v : {e.x(), e.y(), e.z(), tree.length(n), tree.radius(n), tree.birth_time(n)}) {
      append_number(line, v);
      line += '\t';
    }
    line += std::to_string(tree.order(n));
    line += '\t';
    if (tree.kind(n) != OrganKind::kInternode) line += organ_kind_name(tree.kind(n));
    for (const auto& a : attrs) {
      line += '\t';
      if (!std::isnan(a[n])) append_number(line, a[n]);
    }
    line += '\n';
    out << line;
  };

  // Depth first: a node, then its branches ('+', one column right), then its successor ('<',
  // same column, written "^<" to refer to the last entity of that column: this node).
  struct Item {
    NodeId node;
    const char* relation;
  };
  std::vector<Item> stack{{0, "^/"}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    emit(it.node, it.relation);
    const NodeId succ = successor(tree, it.node);
    if (succ != kNoNode) stack.push_back({succ, "^<"});
    std::vector<NodeId> branches;
    for (NodeId c : tree.children(it.node)) {
      if (c != succ) branches.push_back(c);
    }
    for (auto b = branches.rbegin(); b != branches.rend(); ++b) stack.push_back({*b, "+"});
  }
}

}  // namespace fspm

namespace fspm {

TreeGraph parse_mtg(std::string_view text, const std::string& file) {
  return parse_mtg(text, file, default_mtg_tree_options());
}

TreeGraph parse_mtg(std::string_view text, const std::string& file, const MtgTreeOptions& options) {
  std::vector<std::string> warnings;
  const Mtg mtg = read_mtg(text, file, &warnings);
  for (const std::string& w : warnings) warn(w);
  return mtg_to_tree(mtg, options, nullptr, file);
}

}  // namespace fspm
