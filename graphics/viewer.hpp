#pragma once
// Real-time viewer (GLFW window, OpenGL 3.3 core, GLM), drawing every mesh with instanced draws:
// orbit (left drag), pan (right drag or shift + left drag), zoom (wheel), growth steps on [ and ]
// (or left/right arrows), shadows from a sun with variance shadow maps (Pirk 6.2.3, eq.
// 6.10-6.12; variance_shadow.hpp), cascaded on request (shadow_cascades.hpp), toggled with S;
// R resets the view, Esc or Q quits; the frame time is shown in the title. A controls panel
// (Dear ImGui, when fspm was built with it) shows and changes the growth step, shadows and their
// cascades, the level-of-detail distance, the wind's strength (for a tree in the wind,
// viewer_wind.hpp) and the colour attribute, with the frame time and the triangles drawn. The
// ground is the plane under the scene drawn to the horizon, hazing towards the sky's colour with
// distance (aerial perspective). Crown volumes (at kCrownOpacity, as in renders) and translucent
// obstacles (at the opacity of their translucency) are blended after the opaque geometry without
// writing depth, their triangles placed in the world and sorted back to front from the eye whenever
// the camera moves (translucent_sort.hpp). With a screenshot path it renders `frames` frames into
// an offscreen framebuffer, writes the image and returns (tests run it under Xvfb with Mesa's
// software OpenGL).
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "graphics/instance_lod.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/relief_crown.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

struct ViewerWind;  // graphics/viewer_wind.hpp

// What the controls panel shows and changes; a test hook (ViewerOptions::before_frame) may set
// it as the panel's widgets do.
struct ViewerControls {
  int step = 0;  // the growth step shown, 0 .. steps - 1
  bool shadows = true;
  int shadow_cascades = 0;  // ViewerOptions::shadow_cascades, 0 to 4
  // Coarse meshes (or, per plant, the coarsest resolution) from this camera distance on.
  double lod_distance_m = 0.0;
  std::string color_by;        // empty = bark and leaf colours
  double wind_strength = 1.0;  // with ViewerOptions::wind: the swing's scale (0: at rest)
};

// Most cascaded shadow maps before the whole scene's map (ViewerOptions::shadow_cascades).
inline constexpr int kMaxShadowCascades = 4;

struct ViewerOptions {
  int width = 1280;
  int height = 800;
  std::string color_by;    // per-vertex attribute; empty = bark and leaf colours
  std::string screenshot;  // non-empty: render `frames` frames hidden, write this image, return
  int frames = 1;          // frames before the screenshot
  // Without a screenshot: the window closes after this many frames (0: when the user closes it),
  // for scripted runs and tests of the window itself.
  int close_after_frames = 0;
  bool shadows = true;
  // Cascaded shadow maps (shadow_cascades.hpp): this many maps (0 to 4) over slices of the view
  // up to three camera distances away, nearest first, each 1024 texels on a side, before the one
  // map of the whole scene. For landscapes, where one map gives each texel metres of ground;
  // while the camera moves, the cascade drawn longest ago is drawn again each frame. 0: the
  // whole scene's map alone.
  int shadow_cascades = 0;
  // The ground plane under the scene to the horizon (without it, the sky's colour is behind).
  bool ground = true;
  // The camera's starting elevation above the horizontal, looking at the scene's centre (a few
  // degrees: a low view along the ground).
  double pitch_deg = 20.0;
  // The camera's starting azimuth: the eye lies in this direction from the target, degrees
  // counter-clockwise from +x (-0.9 rad).
  double yaw_deg = -51.56620156177409;
  // The point the camera starts looking at (default: the scene's centre) and its distance from
  // it (0: 2.6 bounding radii, framing the scene).
  std::optional<std::array<double, 3>> look_at;
  double camera_distance_m = 0.0;
  // Distance-based level of detail: beyond this multiple of the starting camera distance the
  // coarse meshes (when given) are drawn instead.
  double lod_distance_factor = 1.5;
  // The ring edge length of the coarse meshes (0: not known). When given, they are drawn from
  // the nearer of that distance and the one at which the edge spans at most two pixels: there
  // the coarse image differs from the fine one less than the fine one does from itself when the
  // camera turns by half a pixel (a screen-space error bound, docs/graphics.md).
  double coarse_edge_m = 0.0;
  // The controls panel in the window's top-left corner (drawn into screenshots too); fspm view
  // shows it unless --no-panel. Ignored when fspm was built without Dear ImGui.
  bool panel = false;
  // What the steps' labels count, shown on the panel's step slider: "age" (plant ages, birth
  // times) or "time" (the times of developmental stages, in (0, 1]).
  std::string step_label = "age";
  // A tree in the wind (viewer_wind.hpp): the one step, posed every frame; the time is the
  // wall clock's, or frame / 24 s for a screenshot (so that it is reproducible).
  std::shared_ptr<const ViewerWind> wind;
  // Reynolds' tessellation (2011, 3.3, expression 2) of the opaque triangles up to this level,
  // the new vertices on each triangle's curved PN surface (pn_triangles.hpp): with tessellation
  // shaders (OpenGL 4.0) per edge and triangle every frame (viewer_tessellation.hpp); where the
  // context has none, or with tessellation_on_cpu, on the CPU once, one level for every mesh
  // from the starting camera distance, (1 - d / D_max) L_max rounded up, at most
  // kCpuTessellationTriangles triangles a mesh. 0: off.
  double tessellation_max_level = 0.0;
  double tessellation_distance_m = 0.0;  // D_max; 0: four times the starting camera distance
  bool tessellation_on_cpu = false;
  // Crowns drawn by relief-mapped ray casting of their cubemaps (relief_crown.hpp, Argudo 5.1),
  // with the opaque geometry; they take part in the framing and in the shadows.
  std::vector<ReliefCrown> relief_crowns;
  // Test hook: called before every frame with the frame's number (from 0) and the controls,
  // which it may change as the panel would.
  std::function<void(int frame, ViewerControls& controls)> before_frame;

  // Throws ValueError naming the field: a size or frame count below 1, shadow_cascades outside
  // 0 to kMaxShadowCascades, a negative or non-finite camera distance.
  void validate() const;
};

// The CPU path's budget: a mesh tessellated on the CPU keeps at most this many triangles.
inline constexpr std::size_t kCpuTessellationTriangles = 4'000'000;

struct ViewerStats {
  int frames = 0;
  double mean_frame_ms = 0.0;  // CPU wall time per frame, glFinish included
  // The first frame's: it draws the shadow map, which later frames reuse until the shadow
  // casters change (a new step, the wind, another level-of-detail choice), and compiles shaders.
  double first_frame_ms = 0.0;
  std::size_t triangles = 0;  // of the step shown last (with per-instance LOD: drawn last)
  std::size_t impostors = 0;  // drawn in the last frame (two triangles each, in `triangles`)
  // Shadow maps drawn over all frames, each layer counted (ViewerOptions::shadow_cascades + 1
  // layers in the first frame with shadows, then those whose casters or cascade moved).
  std::size_t shadow_maps_drawn = 0;
  // The tessellation used: "gpu", "cpu" (with its level) or "" (none).
  std::string tessellation;
  int cpu_tessellation_level = 0;
  ViewerControls controls;  // as the last frame left them
};

// True when fspm was built with the viewer (FSPM_WITH_VIEWER).
bool viewer_available();

// True when the viewer has its controls panel (built with Dear ImGui).
bool viewer_panel_available();

// `steps` are the growth steps (one mesh each; one step for a still tree), `labels` their ages,
// `coarse_steps` (empty, or one per step) lower-resolution meshes for distant views.
// Throws ValueError for an unknown colour attribute or no steps, IoError when no OpenGL 3.3
// window can be opened.
ViewerStats run_viewer(const std::vector<TriangleMesh>& steps, const std::vector<double>& labels,
                       const ViewerOptions& options,
                       const std::vector<TriangleMesh>& coarse_steps = {});

// Instanced steps (substructures of compressed graphs, scenes of many plants): each shared mesh
// is uploaded once and drawn with one instanced draw call (glDrawElementsInstanced) per mesh,
// per-instance matrices in a vertex buffer. Colouring by "order" adds each instance's
// order_offset, as the flattened mesh does. Same errors as above.
ViewerStats run_instanced_viewer(const std::vector<InstancedMesh>& steps,
                                 const std::vector<double>& labels, const ViewerOptions& options,
                                 const std::vector<InstancedMesh>& coarse_steps = {});

// A scene of many plants with level of detail per instance (instance_lod.hpp): every frame, the
// plants outside the view are skipped and the others drawn at the resolution and leaf share
// chosen for the camera, or, beyond LodOptions::impostor_distance_m, as impostors
// (viewer_impostors.hpp). One step (no growth). Same errors as above, and ValueError for bad
// level-of-detail options.
ViewerStats run_lod_viewer(const LodScene& scene, const LodOptions& lod_options,
                           const ViewerOptions& options);

}  // namespace fspm::graphics
