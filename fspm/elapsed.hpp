#pragma once
// Wall-clock time since a start point: run times, the models' own timing metrics and the
// "seconds" every command prints with --json.

#include <chrono>

namespace fspm {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace fspm
