#pragma once
// The viewer's controls panel: Dear ImGui with its GLFW and OpenGL 3 back ends, kept in
// viewer_panel_imgui.cpp so that only that file needs ImGui (its own library target). Used by
// viewer_glfw.cpp alone; without ImGui the panel is inactive and draws nothing.
#include <cstddef>
#include <string>
#include <vector>

#include "graphics/viewer.hpp"

struct GLFWwindow;  // opaque here: no GLFW header needed

namespace fspm::graphics {

// What the panel shows but does not change.
struct PanelInfo {
  const std::vector<double>* labels = nullptr;  // the age of each step (may be shorter)
  std::string label_name = "age";               // what the labels count (ViewerOptions)
  int steps = 1;
  std::vector<std::string> attributes;      // colour choices besides the materials' colours
  double lod_min_m = 0.0, lod_max_m = 0.0;  // the distance slider's range; max 0: no LOD
  double frame_ms = 0.0;
  std::size_t triangles = 0;
  bool far = false;   // the coarse meshes are drawn
  bool wind = false;  // a tree in the wind: the wind strength slider
};

class ViewerPanel {
 public:
  // Sets ImGui up on the current OpenGL context of `window` when `enabled` and ImGui is there;
  // its input callbacks are installed ahead of (and call) those already on the window.
  ViewerPanel(GLFWwindow* window, bool enabled);
  ~ViewerPanel();
  ViewerPanel(const ViewerPanel&) = delete;
  ViewerPanel& operator=(const ViewerPanel&) = delete;

  bool active() const { return active_; }
  // Draws the panel over the bound framebuffer of width x height pixels, changing `controls` as
  // its widgets are moved.
  void draw(const PanelInfo& info, ViewerControls& controls, int width, int height);
  // The panel has the mouse (or the keyboard): the viewer's camera and keys leave it alone.
  bool wants_mouse() const;
  bool wants_keyboard() const;

 private:
  void build(const PanelInfo& info, ViewerControls& controls, int width, int height);
  bool active_ = false;
  bool shown_ = false;  // a first frame was laid out
};

}  // namespace fspm::graphics
