#pragma once
// Relief-mapped crowns in offscreen pictures (Argudo 2014, 5.1; graphics/relief_crown.hpp): after
// the rest of the scene is rendered, every pixel's ray is marched through each placed crown on
// the CPU, as the viewer's shader does, and the crown's shaded colour is written where it lies
// nearer than what the picture's depth buffer holds. The offscreen VTK renders use it
// (graphics/render.hpp, RenderOptions::relief_crowns); it needs no OpenGL itself.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "graphics/image.hpp"
#include "graphics/relief_crown.hpp"

namespace fspm::graphics {

struct PictureCamera {
  // World to normalized device coordinates (x, y, z each in [-1, 1], OpenGL's convention).
  Eigen::Matrix4d view_projection = Eigen::Matrix4d::Identity();
  Eigen::Vector3f sun = Eigen::Vector3f::UnitZ();  // unit direction to the light, world
};

// `depth`: the picture's window depths in [0, 1] (OpenGL's, (z_ndc + 1) / 2), width x height,
// row 0 at the bottom as OpenGL reads them; `image` rows top first. Pixels a crown covers
// nearer than their depth take its colour (alpha 255). Returns the pixels written.
std::size_t composite_relief_crowns(const std::vector<ReliefCrown>& crowns,
                                    const PictureCamera& camera, std::span<const float> depth,
                                    Image& image);

}  // namespace fspm::graphics
