// Kept apart from the VTK code because X.h's macros (Success, None ...) clash with Eigen.
#ifdef FSPM_HAVE_X11
#include <X11/Xlib.h>
#endif

#include <chrono>
#include <cstdlib>
#include <thread>

#include "graphics/x_display.hpp"

namespace fspm::graphics {

void* open_x_display() {
  const char* name = std::getenv("DISPLAY");
  if (name == nullptr || *name == '\0') return nullptr;
#ifdef FSPM_HAVE_X11
  for (int attempt = 0; attempt < 30; ++attempt) {
    if (Display* display = XOpenDisplay(name)) return display;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
#endif
  return nullptr;
}

void close_x_display(void* display) {
#ifdef FSPM_HAVE_X11
  if (display != nullptr) XCloseDisplay(static_cast<Display*>(display));
#else
  (void)display;
#endif
}

// Declared in graphics/render.hpp, which cannot be included here (Eigen after X.h).
bool display_available() {
  void* display = open_x_display();
  close_x_display(display);
  return display != nullptr;
}

}  // namespace fspm::graphics
