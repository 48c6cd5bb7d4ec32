// The controls panel with Dear ImGui (Debian's libimgui-dev: a static library with the GLFW and
// OpenGL 3 back ends built in). Compiled into its own target, linked to the viewer only.
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "graphics/viewer_panel.hpp"

namespace fspm::graphics {
namespace {

constexpr float kPanelX = 8.0f, kPanelY = 8.0f;  // pixels from the top-left corner
constexpr float kPanelWidth = 300.0f;

// The step slider, labelled with the step's age.
void step_slider(const PanelInfo& info, ViewerControls& c) {
  const int n = std::max(info.steps, 1);
  c.step = std::clamp(c.step, 0, n - 1);
  const bool aged = info.labels != nullptr && c.step < static_cast<int>(info.labels->size()) &&
                    std::isfinite((*info.labels)[c.step]);
  char format[64];
  if (aged) {
    std::snprintf(format, sizeof(format), "%%d of %d: %s %g", n, info.label_name.c_str(),
                  (*info.labels)[c.step]);
  } else {
    std::snprintf(format, sizeof(format), "%%d of %d", n);
  }
  int shown = c.step + 1;  // counted from 1, as a user counts the ages given
  ImGui::BeginDisabled(n == 1);
  ImGui::SliderInt("step", &shown, 1, n, format, ImGuiSliderFlags_AlwaysClamp);
  ImGui::EndDisabled();
  c.step = shown - 1;
}

// The colour attribute: the materials' colours or one of the meshes' attributes.
void colour_combo(const PanelInfo& info, ViewerControls& c) {
  const char* shown = c.color_by.empty() ? "materials" : c.color_by.c_str();
  if (!ImGui::BeginCombo("colour by", shown)) return;
  if (ImGui::Selectable("materials", c.color_by.empty())) c.color_by.clear();
  for (const std::string& a : info.attributes) {
    if (ImGui::Selectable(a.c_str(), c.color_by == a)) c.color_by = a;
  }
  ImGui::EndCombo();
}

}  // namespace

ViewerPanel::ViewerPanel(GLFWwindow* window, bool enabled) {
  if (!enabled) return;
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the working directory
  ImGui::StyleColorsDark();
  ImGui::GetStyle().Alpha = 0.92f;
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  active_ = true;
}

ViewerPanel::~ViewerPanel() {
  if (!active_) return;
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

bool ViewerPanel::wants_mouse() const { return active_ && ImGui::GetIO().WantCaptureMouse; }

bool ViewerPanel::wants_keyboard() const { return active_ && ImGui::GetIO().WantCaptureKeyboard; }

// One ImGui frame of the panel, not rendered yet.
void ViewerPanel::build(const PanelInfo& info, ViewerControls& c, int width, int height) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGuiIO& io = ImGui::GetIO();
  // The frame drawn (an offscreen target for screenshots) sets the size, not the window.
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
  io.DeltaTime = std::max(io.DeltaTime, 1e-4f);  // two frames within the clock's resolution
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(kPanelX, kPanelY), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0.0f), ImGuiCond_Always);
  ImGui::Begin("fspm view", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  step_slider(info, c);
  ImGui::Checkbox("shadows", &c.shadows);
  if (c.shadows) {
    ImGui::SliderInt("cascades", &c.shadow_cascades, 0, 4, "%d", ImGuiSliderFlags_AlwaysClamp);
  }
  if (info.lod_max_m > info.lod_min_m) {
    float d = static_cast<float>(c.lod_distance_m);
    ImGui::SliderFloat("LOD distance", &d, static_cast<float>(info.lod_min_m),
                       static_cast<float>(info.lod_max_m), "%.1f m",
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    c.lod_distance_m = d;
  }
  if (info.wind) {
    float strength = static_cast<float>(c.wind_strength);
    ImGui::SliderFloat("wind", &strength, 0.0f, 3.0f, "%.2f x", ImGuiSliderFlags_AlwaysClamp);
    c.wind_strength = strength;
  }
  colour_combo(info, c);
  ImGui::Separator();
  ImGui::Text("%.1f ms/frame", info.frame_ms);
  ImGui::Text("%zu triangles%s", info.triangles, info.far ? " (far LOD)" : "");
  ImGui::End();
}

void ViewerPanel::draw(const PanelInfo& info, ViewerControls& c, int width, int height) {
  if (!active_) return;
  if (!shown_) {
    // ImGui lays a new window out on its first frame and shows it from the second: one frame
    // built and dropped, so that the panel is in the first picture (a screenshot of one frame).
    build(info, c, width, height);
    ImGui::EndFrame();
    shown_ = true;
  }
  build(info, c, width, height);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace fspm::graphics
