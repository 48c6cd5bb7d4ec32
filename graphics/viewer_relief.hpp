#pragma once
// The viewer's relief-mapped crowns on the GPU (Argudo 5.1; graphics/relief_crown.hpp): each
// crown's radius and colour cubemaps as textures, and for each placed copy its bounding cube drawn
// (back faces, so the eye may be inside it) with a fragment shader that marches the ray from the
// eye through the bounding sphere to the first point inside the radius cubemap, shades it with the
// sun like the scene shader, and writes that point's depth. For the viewer's own use
// (viewer_glfw.cpp); needs the viewer's OpenGL context current while it lives.
#include <memory>
#include <vector>

#include "graphics/relief_crown.hpp"

namespace fspm::graphics {

class ReliefCrownRenderer {
 public:
  explicit ReliefCrownRenderer(const std::vector<ReliefCrown>& crowns);
  ~ReliefCrownRenderer();
  ReliefCrownRenderer(const ReliefCrownRenderer&) = delete;
  ReliefCrownRenderer& operator=(const ReliefCrownRenderer&) = delete;

  // Column-major 4 x 4 view-projection, the eye and the unit direction to the sun (world).
  void draw(const float* view_projection, const float* eye, const float* sun) const;

 private:
  struct Gpu;
  std::unique_ptr<Gpu> gpu_;
};

}  // namespace fspm::graphics
