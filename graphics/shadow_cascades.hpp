#pragma once
// Cascaded shadow maps for large scenes. One shadow map over a whole landscape gives each texel
// metres of ground, so a tree near the camera casts a blur. Cascades split the camera's view
// frustum by distance into slices and give each slice a map of its own (Engel 2006; Dimitrov
// 2007), the near slices small and finely resolved; beyond the last slice the viewer keeps its
// one map of the whole scene. The split distances follow Zhang et al.'s practical scheme (2006,
// "parallel-split shadow maps"): a blend of the logarithmic split, which gives every slice the
// same texels per pixel, and the uniform one, which keeps the near slices from being tiny.
//
// Each slice's map is the sun's orthographic view of the slice's bounding sphere: its size does
// not change as the camera turns, and its centre is moved to whole texels of the sun's view, so
// a still scene's shadow edges do not crawl as the camera moves (Valient 2007). The depth range
// runs from the scene's point nearest the sun, so every caster between the sun and a slice is in
// its map, to the slice's far side.
//
// The geometry is computed here on the CPU and tested without OpenGL; the viewer draws the maps
// and picks, per pixel, the first slice whose map holds it (viewer_glfw.cpp).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace fspm::graphics {

// Zhang et al.'s practical split scheme: split i of `count` (i = 0 .. count) lies at
// C_i = lambda * n (f / n)^(i / count) + (1 - lambda) * (n + (f - n) i / count), from the near
// distance n (i = 0) to the far distance f (i = count), distances along the view direction.
// lambda = 1: logarithmic, 0: uniform. Throws ValueError unless 0 < n < f, count >= 1 and lambda
// in [0, 1].
std::vector<double> cascade_splits(double near_m, double far_m, int count, double lambda);

// A perspective camera: eye, unit viewing direction, up (not parallel to it), vertical field of
// view and width over height.
struct CascadeCamera {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  Eigen::Vector3d forward = Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double vertical_fov_rad = 0.6981317007977318;  // 40 degrees
  double aspect = 1.0;
};

// The eight corners of the view frustum between distances `near_m` and `far_m` along forward.
std::vector<Eigen::Vector3d> frustum_slice_corners(const CascadeCamera& camera, double near_m,
                                                   double far_m);

// The sun's view: unit axes x, y across the map and z towards the sun (right-handed), with
// +y the projection of world +y where the sun is not along it. The whole-scene map uses the
// same axes, so all maps agree on which way is up.
Eigen::Matrix3d sun_axes(const Eigen::Vector3d& sun);

// Texels of every cascade's map beyond its slice's sphere, on each side: one for the move to
// whole texels, the rest for the blur of the moments and the bilinear lookup, so every point of the
// slice has its filtered shadow in the map (the viewer skips to the next cascade within
// kCascadeGuardTexels - 1 texels of a map's edge).
inline constexpr int kCascadeGuardTexels = 4;

struct ShadowCascade {
  // World to the map's clip space (OpenGL conventions: x, y, z in [-1, 1]; z = -1 nearest the
  // sun).
  Eigen::Matrix4d light_view_projection = Eigen::Matrix4d::Identity();
  double near_m = 0.0, far_m = 0.0;  // the slice, along the view direction
  double radius_m = 0.0;             // of the slice's bounding sphere
  double half_width_m = 0.0;         // of the map: r and kCascadeGuardTexels texels more
  double texel_m = 0.0;              // 2 half_width_m / resolution
  // The light-space box: x, y of the map's centre, and the depths (along the sun) of its
  // nearest and farthest planes; light-space coordinates are sun_axes(sun)^T p.
  Eigen::Vector2d center_xy = Eigen::Vector2d::Zero();
  double depth_near_m = 0.0, depth_far_m = 0.0;
};

// One cascade per slice between consecutive `splits` (cascade_splits), each a map of
// `resolution` texels on a side. `sun` is the unit direction towards the sun; `scene` bounds
// every caster. Throws ValueError for fewer than two splits, a resolution below 16 or an empty
// scene box.
std::vector<ShadowCascade> fit_shadow_cascades(const CascadeCamera& camera,
                                               const std::vector<double>& splits,
                                               const Eigen::Vector3d& sun,
                                               const Eigen::AlignedBox3d& scene, int resolution);

// True when a sphere (centre, radius) may cast a shadow into the cascade's map: it overlaps the
// map's square across the sun and is not wholly beyond its far plane.
bool casts_into(const ShadowCascade& cascade, const Eigen::Matrix3d& axes,
                const Eigen::Vector3d& center, double radius);

}  // namespace fspm::graphics
