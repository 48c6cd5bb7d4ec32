#pragma once
// Progress of a sweep on stderr: a bar redrawn in place with rate and ETA on a terminal, or a
// plain line at most every few seconds otherwise (logs, Slurm output files).
#include <chrono>
#include <cstddef>
#include <iosfwd>

namespace fspm::experiments {

class ProgressReporter {
 public:
  ProgressReporter(std::ostream* out, std::size_t total, bool bar, double interval_s);
  // Prints when due (or always when `final`).
  void update(std::size_t done, std::size_t failed, bool final = false);

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream* out_;
  std::size_t total_;
  bool bar_;
  double interval_s_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = Clock::now();
  bool printed_ = false;
};

}  // namespace fspm::experiments
