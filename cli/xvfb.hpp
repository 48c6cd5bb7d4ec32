#pragma once
// VTK's OpenGL context needs an X display (Debian's VTK has no EGL or OSMesa back end).
namespace fspm::cli {

// Without a display, runs this same command again under a virtual X server (xvfb-run -a) rather
// than failing: exec, so it returns only when there is a display already, when xvfb-run is
// missing, or when this process already runs under it (FSPM_UNDER_XVFB). Call it before anything
// is written.
void rerun_under_xvfb_if_needed();

}  // namespace fspm::cli
