#pragma once
// The viewer's variance shadow maps (Pirk 6.2.3, eq. 6.10-6.12; variance_shadow.hpp): the layers
// of one array texture of depth moments, each the sun's orthographic view of part of the scene.
// With cascades (shadow_cascades.hpp) the first layers hold the slices of the camera's frustum,
// nearest first, and the last layer the whole scene; without, the one layer is the whole scene.
// Needs a current OpenGL context; names OpenGL objects as unsigned integers.
#include <functional>

namespace fspm::graphics {

// Most layers: four cascades and the whole scene (the size of kShadowReceiverGlsl's array).
inline constexpr int kMaxShadowLayers = 5;

// GLSL (without a #version line) that a fragment shader receiving shadows includes: the
// uniforms below and `float lit(vec3 world)`, the light reaching a world point in [0, 1].
extern const char* const kShadowReceiverGlsl;

class ShadowMaps {
 public:
  // `layers` maps of `resolution` texels on a side (1 <= layers <= kMaxShadowLayers).
  ShadowMaps(int resolution, int layers);
  ~ShadowMaps();
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  int layers() const { return layers_; }
  int resolution() const { return resolution_; }

  // Draws layer k with `light_mvp` (column-major 4 x 4, world to the map's clip space): clears
  // it to the far depth (moments (1, 1): nothing there shadows), calls draw_casters(program)
  // with the moments program in use and its light_mvp set (casters with the viewer's vertex
  // attributes: position 0, model matrix 3-6), then blurs the moments along x and y.
  void draw_layer(int k, const float* light_mvp,
                  const std::function<void(unsigned program)>& draw_casters);

  // Sets kShadowReceiverGlsl's uniforms on `program` (in use): shadows on or off, the layers'
  // matrices (layers() of them, column-major, in layer order), each an orthographic view along
  // the unit direction to the sun `sun` with the axes of sun_axes (shadow_cascades.hpp), and
  // binds the maps to texture unit 0.
  void use_in(unsigned program, bool shadows, const float* light_mvps, const float* sun) const;

 private:
  int resolution_ = 0, layers_ = 0;
  unsigned moments_ = 0, scratch_ = 0;  // RG32F arrays: `layers_` layers and one
  unsigned layer_fbo_[kMaxShadowLayers] = {}, scratch_fbo_ = 0, depth_rb_ = 0;
  unsigned moments_program_ = 0, blur_program_ = 0, triangle_vao_ = 0;
};

}  // namespace fspm::graphics
