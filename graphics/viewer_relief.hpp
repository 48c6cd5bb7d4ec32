#pragma once
// The viewer's relief-mapped crowns on the GPU (Argudo 5.1; graphics/relief_crown.hpp): each
// crown's radius and colour cubemaps as textures, and for each placed copy its bounding cube drawn
// (back faces, so the eye may be inside it) with a fragment shader that marches the ray from the
// eye through the bounding sphere to the first point inside the radius cubemap, shades it with the
// sun like the scene shader (shadows included), and writes that point's depth; the same march from
// the sun writes the crowns' depth moments into the variance shadow map, so they cast shadows. For
// the viewer's own use (viewer_glfw.cpp); needs the viewer's OpenGL context current while it lives.
#include <memory>
#include <string>
#include <vector>

#include "graphics/relief_crown.hpp"

namespace fspm::graphics {

class ReliefCrownRenderer {
 public:
  // `shadow_glsl`: the viewer's variance-shadow GLSL (lit() and its uniforms), which the crowns'
  // fragment shader calls to receive shadows.
  ReliefCrownRenderer(const std::vector<ReliefCrown>& crowns, const std::string& shadow_glsl);
  ~ReliefCrownRenderer();
  ReliefCrownRenderer(const ReliefCrownRenderer&) = delete;
  ReliefCrownRenderer& operator=(const ReliefCrownRenderer&) = delete;

  // The program, for the caller to set the shadow uniforms of `shadow_glsl` on.
  unsigned program() const;
  // The camera pass. Column-major 4 x 4 matrices, the eye and the unit direction to the sun
  // (world); the sun's matrix places each point in the shadow map.
  void draw(const float* view_projection, const float* eye, const float* sun,
            const float* light_mvp) const;
  // The moments pass of the variance shadow map: the crowns seen by the sun, orthographic.
  void draw_moments(const float* light_mvp, const float* sun) const;

 private:
  template <typename PerPlacement>
  void draw_cubes(const float* view_projection, const float* sun,
                  const PerPlacement& per_placement) const;
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
};

}  // namespace fspm::graphics
