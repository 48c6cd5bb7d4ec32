#pragma once
// What the commands that draw files make of an input, from its file kind (fspm/file_kind.hpp): a
// tree file, a compressed graph (.ctree), a GreenLab plant description (.toml, simulated on the
// fly), a scene of many plants (.json), a ParaView growth sequence (.pvd, viewer only), an
// L-system (.l, drawn by the turtle) or a mesh placed as it is (a crown from fspm crown).
#include <string>

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

}  // namespace fspm::io
