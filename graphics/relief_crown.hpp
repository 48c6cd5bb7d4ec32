#pragma once
// A crown drawn by relief-mapped ray casting (Argudo 2014, 5.1): instead of its triangles, the
// crown's radius cubemap R(d) (metres from its centre to the surface along the unit direction d)
// and colour cubemap, as `fspm crown` writes them (crown/cubemap.hpp: six N x N faces side by
// side, front -y, right +x, back +y, left -x, top +z, bottom -z, row 0 at the top). A ray from the
// eye marches through the crown's bounding sphere and stops at the first point p with
// |p - centre| <= R(p - centre); the colour is the colour cubemap's in that direction. The viewer
// draws it so (graphics/viewer.hpp); the lookup here is the one its shader uses.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace fspm::graphics {

struct ReliefCrown {
  int face_size = 0;                                   // N
  std::vector<float> radius_m;                         // 6N x N, row-major strip
  std::vector<std::uint8_t> rgb;                       // 6N x N x 3, the same strip
  Eigen::Vector3f centre_m = Eigen::Vector3f::Zero();  // in the crown's own frame
  // World from the crown's frame, one per placed copy: rotation times uniform scale, translation.
  std::vector<Eigen::Matrix4f> placements{Eigen::Matrix4f::Identity()};

  // The largest radius: the bounding sphere the rays march through.
  float max_radius_m() const;
};

// Throws ValueError unless face_size >= 1, both strips hold 6N x N texels (three bytes each for
// the colour), every radius is finite and >= 0 with at least one above 0, and every placement is
// finite with an invertible rotation-and-scale.
void validate(const ReliefCrown& crown);

// R(d) for a direction d (not zero): the strip sampled bilinearly within d's face, clamped half a
// texel from its edges, as the viewer's shader does.
float relief_radius_m(const ReliefCrown& crown, const Eigen::Vector3f& direction);

}  // namespace fspm::graphics
