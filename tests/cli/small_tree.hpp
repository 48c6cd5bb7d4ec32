#pragma once
// A small tree file for command-line tests of meshes and renders.
#include <filesystem>
#include <string>

#include "fspm/tree_file.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::testing {

// Two internodes up z (radius 0.05 m, born 0 and 1) and a leaf on the top one (born 2), with the
// attribute "light" = 0.5; written to DIR/t.tree, whose path is returned.
inline std::string write_small_tree(const std::filesystem::path& dir) {
  TreeGraph t;
  NodeData d;
  d.end = {0, 0, 1};
  d.radius = 0.05;
  NodeId a = t.add_node(kNoNode, d);
  d.start = {0, 0, 1};
  d.end = {0, 0, 2};
  d.birth_time = 1;
  NodeId b = t.add_node(a, d);
  d.start = {0, 0, 2};
  d.end = {0.2, 0, 2};
  d.radius = 0;
  d.birth_time = 2;
  d.kind = OrganKind::kLeaf;
  t.add_node(b, d);
  t.add_attribute("light", 0.5);
  const std::string path = (dir / "t.tree").string();
  write_tree_file(t, path);
  return path;
}

}  // namespace fspm::testing
