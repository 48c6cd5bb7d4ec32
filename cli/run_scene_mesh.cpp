#include "cli/run_scene_mesh.hpp"

#include "experiments/render_selection.hpp"
#include "io/obstacle_crop.hpp"
#include "io/obstacle_mesh.hpp"

namespace fspm::cli {

graphics::TriangleMesh run_scene_mesh(const experiments::Experiment& x,
                                      const experiments::RunRecord& record, const std::string& dir,
                                      const graphics::MeshOptions& options, Obstacles& obstacles) {
  graphics::TriangleMesh mesh =
      graphics::mesh_tree(experiments::recorded_run_tree(x, record, dir), options);
  obstacles = Obstacles::kNone;
  if (const std::optional<environment::Scene> scene = experiments::recorded_run_scene(x, record)) {
    Eigen::Vector2d region_lo, region_hi;
    io::obstacle_region(mesh.bbox_min().cast<double>(), mesh.bbox_max().cast<double>(), region_lo,
                        region_hi);
    const graphics::TriangleMesh stones =
        io::mesh_obstacles(io::obstacles_near(*scene, region_lo, region_hi));
    obstacles = stones.triangle_count() > 0 ? Obstacles::kDrawn : Obstacles::kFarAway;
    mesh.append(stones);
  }
  return mesh;
}

}  // namespace fspm::cli
