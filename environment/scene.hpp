#pragma once
// A scene: the sky and every occluder, z up.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "environment/occluders.hpp"
#include "environment/sky.hpp"

namespace fspm::environment {

struct Scene {
  Sky sky;
  std::vector<Sphere> spheres;  // leaf clusters and spherical obstacles
  std::vector<Box> boxes;       // boxes and walls
  std::vector<TriangleMesh> meshes;
  std::optional<Ground> ground;

  // True when p lies inside a solid occluder (a solid box or sphere, or below a solid ground).
  bool inside_solid(const Eigen::Vector3d& p) const;
  // True when the segment from a to b enters a solid occluder or crosses a solid mesh.
  bool segment_blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const;
};

// The scene with every occluder moved by `offset_m` (the sky and a horizontal ground are unchanged
// by a horizontal move; the ground follows a vertical one). Moving the scene by -p puts a tree
// standing at the origin at p without touching the tree, so its analysis can be reused.
Scene translated(const Scene& scene, const Eigen::Vector3d& offset_m);

}  // namespace fspm::environment
