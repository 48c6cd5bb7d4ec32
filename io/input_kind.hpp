#pragma once
// What the commands that draw files make of an input, from its file kind (fspm/file_kind.hpp): a
// tree file, a compressed graph (.ctree), a GreenLab plant description (.toml, simulated on the
// fly), a scene of many plants (.json), a ParaView growth sequence (.pvd, viewer only), an
// L-system (.l, drawn by the turtle) or a mesh placed as it is (a crown from fspm crown).
#include <string>
#include <string_view>

#include "fspm/mtg_tree.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::io {

enum class InputKind { kTree, kCompressed, kPlant, kScene, kPvd, kLsystem, kMesh };

// Anything that is none of the others is read as a tree (and fails there with the tree reader's
// message).
InputKind input_kind(const std::string& path);

// A .ctree or a GreenLab plant: meshed per substructure.
bool is_compressed(InputKind kind);

// The folder fspm crown wrote (OUT/ holding crown.glb) stands for its crown, as in scene files;
// any other path is returned as it is.
std::string resolve_crown_folder(const std::string& path);

// read_tree_file with `format`, or, when none is given and the extension names no kind, the
// format the file's first bytes tell (fspm/file_kind.hpp).
TreeGraph read_tree_input(const std::string& path, std::string_view format);
TreeGraph read_tree_input(const std::string& path, std::string_view format,
                          const MtgTreeOptions& mtg);

}  // namespace fspm::io
