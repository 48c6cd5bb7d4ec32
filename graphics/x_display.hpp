#pragma once
// One X connection for VTK's render window. Opened by us (with retries: a busy virtual server
// sometimes refuses a connection made right after another) and handed to VTK, so VTK never
// aborts on a failed connection of its own. Opaque pointers keep Xlib out of every header.
namespace fspm::graphics {

// The Display* for $DISPLAY, or nullptr when none can be opened.
void* open_x_display();
void close_x_display(void* display);

}  // namespace fspm::graphics
