#pragma once
// A tree swaying in the wind in the viewer (Reynolds 3.3, Pirk 6.1): the tree's skinned mesh
// (bones from its skeleton with Reynolds' weights, skeleton_skin.hpp) posed on the CPU every
// frame by linear blend skinning, with the joint rotations of the wind model (wind_animation.hpp)
// at the frame's time. The panel's wind strength scales every joint's swing (0: at rest), as a
// stronger or weaker wind of the same gusts would.
#include <Eigen/Core>
#include <vector>

#include "graphics/skeleton_skin.hpp"
#include "graphics/triangle_mesh.hpp"
#include "graphics/wind_animation.hpp"

namespace fspm::graphics {

struct ViewerWind {
  TriangleMesh mesh;  // the tree at rest, with bone weights: the viewer's one step
  Skin skin;          // of `mesh` (skin_mesh)
  WindOptions wind;

  // Positions and normals of `mesh` at time t_s, the swing scaled by `strength` (>= 0).
  void pose(double t_s, double strength, std::vector<Eigen::Vector3f>& positions,
            std::vector<Eigen::Vector3f>& normals) const;
};

}  // namespace fspm::graphics
