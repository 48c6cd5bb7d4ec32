#pragma once
// --max-order and --merge-collinear: the level of detail by exploring the graph (Jaeger et al.
// 2010, 3.1.1) on the commands that reconstruct or mesh plants.
#include <CLI/CLI.hpp>

#include "fspm/instanced_lod.hpp"

namespace fspm::cli {

struct GraphLodArguments {
  int max_order = -1;  // < 0: every order
  bool merge_collinear = false;

  LevelOfDetail lod() const {
    LevelOfDetail l;
    if (max_order >= 0) l.max_order = max_order;
    l.merge_collinear = merge_collinear;
    return l;
  }
};

inline void add_graph_lod_options(CLI::App* command, GraphLodArguments& arguments) {
  command
      ->add_option("--max-order", arguments.max_order,
                   "Level of detail: leave out branches (and leaves) of a higher branching order "
                   "than N (the trunk is order 0)")
      ->check(CLI::Range(0, 65535));
  command->add_flag("--merge-collinear", arguments.merge_collinear,
                    "Level of detail: merge consecutive internodes of the same direction with "
                    "nothing growing between them into one");
}

}  // namespace fspm::cli
