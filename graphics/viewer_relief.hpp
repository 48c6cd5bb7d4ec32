#pragma once
// The viewer's relief-mapped crowns on the GPU (Argudo 5.1; graphics/relief_crown.hpp): each
// crown's radius and colour cubemaps as textures, and for each placed copy its bounding cube drawn
// (back faces, so the eye may be inside it) with a fragment shader that marches the ray from the
// eye through the bounding sphere to the first point inside the radius cubemap, shades it with the
// sun like the scene shader (shadows included), and writes that point's depth; the same march from
// the sun writes the crowns' depth moments into the variance shadow map, so they cast shadows. A
// crown with billboard centres that is large on the screen is drawn instead as Argudo's detailed
// crown (5.2): instanced squares of leaves facing the eye, cropped to the radius cubemap; its
// shadow is still the relief's. Both forms are shaded by Argudo 5.3's three terms. For
// the viewer's own use (viewer_glfw.cpp); needs the viewer's OpenGL context current while it lives.
#include <array>
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

  // The programs (relief, billboards), for the caller to set the shadow uniforms of
  // `shadow_glsl` on.
  std::array<unsigned, 2> programs() const;
  // The camera pass. A column-major 4 x 4 matrix, the eye and the unit direction to the sun
  // (world); the shadow maps are those of the uniforms set on programs().
  void draw(const float* view_projection, const float* eye, const float* sun) const;
  // The moments pass of the variance shadow map: the crowns seen by the sun, orthographic.
  void draw_moments(const float* light_mvp, const float* sun) const;

 private:
  // Per placement of every crown, per_placement(crown, model) says whether to draw its cube (and
  // sets the placement's uniforms), or how many billboards to draw (0: none).
  template <typename PerPlacement>
  void draw_cubes(const float* view_projection, const float* sun,
                  const PerPlacement& per_placement) const;
  template <typename PerPlacement>
  void draw_billboards(const float* view_projection, const float* sun,
                       const PerPlacement& per_placement) const;
  // Binds each crown that use(crown) accepts, sets each of its placements' model matrix on the
  // program and calls draw(crown, model).
  template <typename Use, typename Draw>
  void each_placement(unsigned program, const Use& use, const Draw& draw) const;
  void bind_crown(unsigned program, const void* crown) const;
  // Uses the program and sets what every crown of a pass shares.
  void begin_pass(unsigned program, const float* view_projection, const float* sun) const;
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
};

}  // namespace fspm::graphics
