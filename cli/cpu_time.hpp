#pragma once
// CPU time of the calling thread, beside the wall-clock "seconds" a command prints: on a loaded
// machine the wall-clock time of the same work is longer by the time the thread waited for a core,
// while a benchmark's CPU column does not count that wait.
#include <time.h>

namespace fspm::cli {

inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace fspm::cli
