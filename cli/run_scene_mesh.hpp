#pragma once
// The tree of a recorded run meshed with the obstacles of its scene that lie near it: what the
// report's renders and 3D views show.
#include "experiments/experiment.hpp"
#include "experiments/run_record.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::cli {

// What a picture of a run shows besides the tree.
enum class Obstacles { kNone, kFarAway, kDrawn };

// The run's tree (experiments/render_selection.hpp: read back or regrown) meshed with `options`,
// with its scene's obstacles cut to the region around it (io/obstacle_crop.hpp) appended;
// `obstacles` says whether there were any and whether they were near enough to be drawn.
graphics::TriangleMesh run_scene_mesh(const experiments::Experiment& experiment,
                                      const experiments::RunRecord& record, const std::string& dir,
                                      const graphics::MeshOptions& options, Obstacles& obstacles);

}  // namespace fspm::cli
