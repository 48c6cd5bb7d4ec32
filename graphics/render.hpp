#pragma once
// Offscreen figures of a tree mesh with VTK: key/fill lighting, ground under the tree out to the
// picture's edges, colouring by a per-vertex attribute with a scalar bar, fixed camera views. VTK
// needs an X display for its OpenGL context here (Debian's VTK has no EGL/OSMesa back end); the
// window itself is never shown, so a virtual server (xvfb-run -a) is enough.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>

#include "fspm/image_request.hpp"
#include "graphics/image.hpp"
#include "graphics/instance_lod.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/relief_crown.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

// The camera directions and their names live in the core (fspm/image_request.hpp).
using fspm::View;
using fspm::view_from_name;

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
  // With ortho_height_m > 0 and a unit ("m", "model units"): a black scale bar in the lower left
  // corner, a round length (1, 2 or 5 times a power of ten) close to a fifth of the image height,
  // labelled with its length and this unit.
  std::string scale_bar_unit;
  // The box the camera is aimed at and fits (the ground plane lies under it); nullopt: the mesh's
  // bounds. Figures at one common scale give every tree a box of the same height from the ground,
  // so the ground lies on the same image row in each.
  std::optional<Eigen::AlignedBox3f> frame;
  // Crowns drawn by relief-mapped ray casting of their cubemaps (relief_crown.hpp, Argudo 5.1)
  // into the rendered picture (relief_composite.hpp), lit by the key light without shadows; they
  // take part in the framing unless `frame` is given.
  std::vector<ReliefCrown> relief_crowns;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// The height in metres a parallel projection along `view` needs to show all of the box [lo, hi]
// in an image of `aspect` = width / height: the box's extent along the view's up direction, or
// its extent across divided by the aspect, whichever is larger (iso: its diagonal for both).
double ortho_height_to_fit(View view, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi,
                           double aspect);

// The scale bar's length for an image `height_m` high: the largest 1, 2 or 5 times a power of ten
// not above a fifth of it (a fifth of 9 m is 1.8 m: 1 m). 0 for a height that is not positive.
double scale_bar_length(double height_m);

// "WxH" -> width, height; throws ValueError.
void parse_size(std::string_view text, int& width, int& height);
// width, height -> "WxH", the inverse of parse_size.
std::string size_text(int width, int height);

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

// A scene of many plants with level of detail per instance (instance_lod.hpp) for the camera of
// `options`: plants outside its view are left out, the others drawn at the resolution and leaf
// share chosen for their distance. `triangles_drawn` (optional) receives the triangles drawn.
// Same errors as render_scene, and ValueError with color_by or bad level-of-detail options.
Image render_lod_scene(const LodScene& scene, const LodOptions& lod, const RenderOptions& options,
                       std::size_t* triangles_drawn = nullptr);

}  // namespace fspm::graphics
