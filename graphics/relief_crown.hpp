#pragma once
// A crown drawn by relief-mapped ray casting (Argudo 2014, 5.1): instead of its triangles, the
// crown's radius cubemap R(d) (metres from its centre to the surface along the unit direction d)
// and colour cubemap, as `fspm crown` writes them (crown/cubemap.hpp: six N x N faces side by
// side, front -y, right +x, back +y, left -x, top +z, bottom -z, row 0 at the top). A ray from the
// eye marches through the crown's bounding sphere and stops at the first point p with
// |p - centre| <= R(p - centre); the colour is the colour cubemap's in that direction. The viewer
// draws it so (graphics/viewer.hpp); the lookup here is the one its shader uses.
//
// Close up the relief looks smooth, so a crown with billboard centres is drawn near the camera
// as Argudo's detailed crown (5.2): a square of leaves facing the camera at each centre, cropped
// to the crown by the radius cubemap, as many of them (in their order) as the crown's size on the
// screen asks for, the last few fading in; and both forms are shaded by his three terms (5.3):
// height in the crown, depth below its surface, and the sun's angle.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

namespace fspm::graphics {

struct ReliefCrown {
  int face_size = 0;                                   // N
  std::vector<float> radius_m;                         // 6N x N, row-major strip
  std::vector<std::uint8_t> rgb;                       // 6N x N x 3, the same strip
  Eigen::Vector3f centre_m = Eigen::Vector3f::Zero();  // in the crown's own frame
  // Billboard centres of the detailed crown in the crown's frame, in drawing order
  // (crown/billboard_cloud.hpp: every prefix covers the crown); empty: always ray cast.
  std::vector<Eigen::Vector3f> billboards_m;
  // World from the crown's frame, one per placed copy: rotation times uniform scale, translation.
  std::vector<Eigen::Matrix4f> placements{Eigen::Matrix4f::Identity()};

  // The largest radius: the bounding sphere the rays march through.
  float max_radius_m() const;
  // The world box around every placed copy's cube about that sphere (how pictures frame it).
  Eigen::AlignedBox3f placed_bounds() const;

  // Throws ValueError unless face_size >= 1, both strips hold 6N x N texels (three bytes each for
  // the colour), every radius is finite and >= 0 with at least one above 0, and every placement is
  // finite with an invertible rotation-and-scale, and the billboard centres are finite.
  void validate() const;
};

// R(d) for a direction d (not zero): the strip sampled bilinearly within d's face, clamped half a
// texel from its edges, as the viewer's shader does.
float relief_radius_m(const ReliefCrown& crown, const Eigen::Vector3f& direction);
// The colour cubemap in direction d (not zero), bilinear as the radius, each channel in [0, 1].
Eigen::Vector3f relief_color(const ReliefCrown& crown, const Eigen::Vector3f& direction);

// The viewer's march on the CPU (for offscreen renders): the ray origin + t dir (crown frame,
// dir a unit vector) through the crown's bounding sphere of radius `bound_m` (1.01
// max_radius_m(), which the caller computes once) in kReliefSteps equal steps from where it
// enters, then 16 bisections of the step in which it first meets |p - centre| <= R(p - centre).
// True and t of that point, or false when the ray misses.
inline constexpr int kReliefSteps = 96;
bool relief_ray_hit(const ReliefCrown& crown, float bound_m, const Eigen::Vector3f& origin,
                    const Eigen::Vector3f& dir, float& t);

// Argudo 5.3's shading of a crown point q (from the centre, crown frame, z up) whose surface lies
// surface_r away in its direction, with outward normal n and the unit direction to the sun (both
// world), as the viewer's shader does without shadows: occlusion by height and depth times
// (0.35 + 0.65 max(n . sun, 0)), then the viewer's gamma (1 / 1.2). Channels in [0, 1].
Eigen::Vector3f relief_shade(const Eigen::Vector3f& albedo, const Eigen::Vector3f& q,
                             float surface_r, float bound, const Eigen::Vector3f& n,
                             const Eigen::Vector3f& sun);

// Argudo 5.2: a crown whose radius appears `radius_px` pixels on the screen is ray cast below
// kBillboardFromPx and drawn with billboards above it, all of them from kAllBillboardsPx on and
// in between a share growing with the crown's area on the screen, never fewer than
// kFewestBillboards; fewer billboards are drawn larger, keeping their summed area. The count is
// fractional: the last kBillboardFade drawn fade in.
inline constexpr float kBillboardFromPx = 140.0f;
inline constexpr float kAllBillboardsPx = 320.0f;
inline constexpr float kFewestBillboards = 16.0f;
inline constexpr float kBillboardFade = 12.0f;
// 0 (ray cast) or the fractional number of billboards to draw, at most `available`.
float billboard_count(float radius_px, std::size_t available);
// Side of a billboard's square as a share of the crown's largest radius: 320 centres in the
// ball are about 0.24 R apart, so squares of 0.5 R overlap into a closed crown.
inline constexpr float kBillboardSide = 0.5f;

}  // namespace fspm::graphics
