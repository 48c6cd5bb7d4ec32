#pragma once
// VTK's OpenGL context needs an X display (Debian's VTK has no EGL or OSMesa back end).
#include <string>
#include <vector>

namespace fspm::cli {

// Without a display, runs this same command again under a virtual X server (xvfb-run -a) rather
// than failing: exec, so it returns only when there is a display already, when xvfb-run is
// missing, or when this process already runs under it (FSPM_UNDER_XVFB). Call it before anything
// is written.
void rerun_under_xvfb_if_needed();

// The command run again under xvfb-run reads its inputs a second time: a pipe or FIFO, already
// drained by the first read, would block it for ever. Where that rerun will happen, such an input
// is refused (IoError naming it) before anything reads it. Empty paths are skipped.
void check_inputs_readable_twice(const std::vector<std::string>& paths);

}  // namespace fspm::cli
