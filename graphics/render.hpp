#pragma once
// Offscreen figures of a tree mesh with VTK: key/fill lighting, a ground plane under the tree,
// colouring by a per-vertex attribute with a scalar bar, fixed camera views. VTK needs an X
// display for its OpenGL context here (Debian's VTK has no EGL/OSMesa back end); the window
// itself is never shown, so a virtual server (xvfb-run -a) is enough.
#include <string>
#include <string_view>

#include "graphics/image.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

enum class View { kFront, kSide, kTop, kIso };

// "front" (looking along +y), "side" (along -x), "top" (down -z), "iso"; throws ValueError.
View view_from_name(std::string_view name);

struct RenderOptions {
  int width = 1024;
  int height = 768;
  View view = View::kIso;
  std::string color_by;  // per-vertex attribute; empty = bark and leaf colours
  bool ground = true;
  bool scalar_bar = true;  // only when colouring by an attribute
  // > 0: parallel projection in which the image height spans this many metres, centred on the
  // tree (figures with a known scale); 0: perspective framing the tree.
  double ortho_height_m = 0.0;
};

// "WxH" -> width, height; throws ValueError.
void parse_size(std::string_view text, int& width, int& height);

// True when fspm was built with VTK (FSPM_WITH_VTK).
bool render_available();

// True when an X display can be opened (VTK's OpenGL context needs one).
bool display_available();

// Throws ValueError for an unknown colour attribute (before touching VTK), for a bad size or
// when built without VTK; IoError when no display can be opened.
Image render_mesh(const TriangleMesh& mesh, const RenderOptions& options);

// An instanced scene: each shared mesh uploaded once and drawn with GPU instancing (VTK's glyph
// mapper, one glyph per instance). Colouring by an attribute renders the flattened mesh instead.
// Same errors as render_mesh.
Image render_scene(const InstancedMesh& scene, const RenderOptions& options);

}  // namespace fspm::graphics
