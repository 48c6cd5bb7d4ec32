#pragma once
// An input of the viewer loaded once and meshed at each growth step: a tree (to a birth time, or
// a developmental stage, Pirk 5), a compressed plant (to a plant age), an L-system drawn once, a
// crown's mesh or a scene; several placed side by side.
#include <memory>
#include <string>
#include <vector>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/instanced_lod.hpp"
#include "fspm/tree_graph.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"
#include "io/input_kind.hpp"
#include "lsystem/lsystem_drawing.hpp"
#include "stages/developmental_model.hpp"

namespace fspm::io {

struct SteppedInput {
  std::string path;
  InputKind kind = InputKind::kTree;
  TreeGraph tree;
  CompressedTreeGraph graph;
  lsystem::LsystemDrawing drawing;  // an L-system, drawn once
  graphics::TriangleMesh mesh;      // a crown from fspm crown, read once
  LevelOfDetail lod;
  // The tree's developmental model (Pirk 5), if its stages are drawn: the stage at time `age`.
  std::shared_ptr<const stages::DevelopmentalModel> model;

  // `age`: plant age for compressed graphs, latest birth time for trees, the stage's time in
  // (0, 1] with a developmental model, ignored for scenes; infinity = everything.
  graphics::InstancedMesh at(double age, const graphics::MeshOptions& options) const;
};

// Every input meshed at every age (instanced), placed side by side along x with a gap of a
// tenth of the widest. All the steps are held at once, so before each is made the steps so far,
// `held_bytes` the caller already holds (the detailed steps, when these are the far ones) and the
// bound of one more (the inputs' full meshes) are checked against the memory limit.
std::vector<graphics::InstancedMesh> steps_side_by_side(const std::vector<SteppedInput>& inputs,
                                                        const std::vector<double>& ages,
                                                        const graphics::MeshOptions& options,
                                                        double held_bytes = 0.0);

// The bytes an instanced mesh holds: its shared meshes and its instances.
double stored_bytes(const graphics::InstancedMesh& mesh);

}  // namespace fspm::io
