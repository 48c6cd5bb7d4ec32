#pragma once
// The viewer's impostors of distant plants on the GPU (impostor.hpp): every view of every plant
// of a level-of-detail scene drawn once, at start-up, into two mipmapped texture arrays (albedo
// and normal in the plant's frame with the depth of what the view saw, premultiplied by coverage:
// the background is zero, so mipmaps average only what the plant covers); each frame the
// impostors' quads facing the eye, shaded by the sun as each instance is turned and shadowed
// through the variance shadow map at the depth each view saw, and
// the same quads facing the sun for the moments pass, so impostors cast shadows too. For the
// viewer's own use (viewer_glfw.cpp); needs the viewer's OpenGL context current while it lives.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "graphics/impostor.hpp"

namespace fspm::graphics {

class ImpostorRenderer {
 public:
  // draw_plant(p) draws plant p's finest mesh (every leaf) in its own frame, opaque triangles
  // only, with the program in use, whose vertex attributes are the viewer's (position 0, normal
  // 1, colour 2, model matrix 3-6). `resolution` is the side of each view in pixels;
  // `shadow_glsl` the viewer's variance-shadow GLSL (lit() and its uniforms).
  ImpostorRenderer(const LodScene& scene, const ImpostorViews& views, int resolution,
                   const std::function<void(std::size_t plant)>& draw_plant,
                   const std::string& shadow_glsl);
  ~ImpostorRenderer();
  ImpostorRenderer(const ImpostorRenderer&) = delete;
  ImpostorRenderer& operator=(const ImpostorRenderer&) = delete;

  // The camera pass's program, for the caller to set the shadow uniforms of `shadow_glsl` on.
  unsigned program() const;
  // This frame's quads: the impostors of `choice` facing `eye` and facing the unit direction
  // `sun` (world).
  void place(const std::vector<InstanceLod>& choice, const float* eye, const float* sun);
  std::size_t quads() const;
  // The camera pass (a column-major 4 x 4 matrix), alpha-tested, writing depth; the shadow maps
  // are those of the uniforms set on program().
  void draw(const float* view_projection) const;
  // The moments pass of the variance shadow map.
  void draw_moments(const float* light_mvp) const;

 private:
  void render_views(const std::function<void(std::size_t plant)>& draw_plant, int resolution);
  const LodScene* scene_;
  ImpostorViews views_;
  std::vector<ImpostorVertex> facing_eye_, facing_sun_;
  Eigen::Vector3f sun_ = Eigen::Vector3f::UnitZ(), eye_ = Eigen::Vector3f::Zero();  // place()'s
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
};

}  // namespace fspm::graphics
