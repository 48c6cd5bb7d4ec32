// A program built on the installed fspm C++ package (find_package(fspm) in CMakeLists.txt): reads
// a tree file, grows a tree of Pirk's type A, simulates a GreenLab plant, and compares them by
// the constrained edit distance (Zhang 1996, as fspm distance computes it).
//   fspm_downstream TREE_FILE PLANT_TOML
#include <cstdint>
#include <exception>
#include <iostream>

#include "environment/growth_model.hpp"
#include "environment/growth_params.hpp"
#include "fspm/constrained_edit_distance.hpp"
#include "fspm/tree_file.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/simulation.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fspm_downstream TREE_FILE PLANT_TOML\n";
    return 2;
  }
  try {
    const fspm::TreeGraph read = fspm::read_tree_file(argv[1]);
    std::cout << "read_nodes " << read.size() << '\n';

    fspm::environment::GrowthParams params = fspm::environment::growth_preset("A");
    params.years = 6;
    const fspm::environment::GrowthResult grown = fspm::environment::grow_tree(params);
    std::cout << "grown_internodes " << grown.internodes << '\n';
    std::cout << "grown_height_m " << grown.height_m << '\n';

    const fspm::greenlab::PlantParams plant = fspm::greenlab::read_plant_params(argv[2]);
    const fspm::CompressedTreeGraph compressed = fspm::greenlab::simulate_compressed(plant);
    const fspm::greenlab::OrganCounts organs = fspm::greenlab::count_organs(compressed);
    std::cout << "greenlab_metamers " << organs.metamers << '\n';
    fspm::greenlab::ReconstructionOptions options;
    options.leaves = false;
    options.flowers = false;
    const fspm::TreeGraph plant_tree = fspm::greenlab::reconstruct(compressed, options);
    std::cout << "greenlab_nodes " << plant_tree.size() << '\n';

    std::cout << "distance_read_read " << fspm::constrained_edit_distance(read, read).distance
              << '\n';
    std::cout << "distance_read_grown "
              << fspm::constrained_edit_distance(read, grown.tree).distance << '\n';
    std::cout << "distance_grown_greenlab "
              << fspm::constrained_edit_distance(grown.tree, plant_tree).distance << '\n';
  } catch (const std::exception& error) {  // fspm::Error: file, line and what was expected
    std::cerr << "fspm_downstream: " << error.what() << '\n';
    return 1;
  }
  return 0;
}
