// The viewer without Dear ImGui: no panel.
#include "graphics/viewer_panel.hpp"

namespace fspm::graphics {

ViewerPanel::ViewerPanel(GLFWwindow*, bool) {}
ViewerPanel::~ViewerPanel() = default;
bool ViewerPanel::wants_mouse() const { return false; }
bool ViewerPanel::wants_keyboard() const { return false; }
void ViewerPanel::draw(const PanelInfo&, ViewerControls&, int, int) {}

}  // namespace fspm::graphics
