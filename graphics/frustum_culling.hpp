#pragma once
// Culling of instances against the view frustum (Argudo 2014, chapter 6: only the trees in
// view are drawn). The six planes come from the view-projection matrix (Gribb and Hartmann's
// extraction, OpenGL clip space -w <= x, y, z <= w); an instance is culled when the bounding
// sphere of its placed mesh lies wholly outside one plane. The test is conservative: an instance
// with any point in view is never culled, one near a frustum corner may be kept.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <vector>

#include "graphics/instanced_mesh.hpp"

namespace fspm::graphics {

struct Frustum {
  // a x + b y + c z + d >= 0 inside; (a, b, c) of unit length.
  std::array<Eigen::Vector4d, 6> planes;
};

// Throws ValueError for a matrix with non-finite entries or a degenerate plane.
Frustum frustum_from_matrix(const Eigen::Matrix4d& view_projection);

bool sphere_outside(const Frustum& frustum, const Eigen::Vector3d& center, double radius);

struct BoundingSphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

// The sphere about the bounding box centre through its farthest vertex (empty mesh: radius 0).
BoundingSphere bounding_sphere(const TriangleMesh& mesh);

// The instances (indices into scene.instances) whose placed bounding sphere is not outside.
std::vector<std::size_t> visible_instances(const InstancedMesh& scene,
                                           const Eigen::Matrix4d& view_projection);

}  // namespace fspm::graphics
