// libFuzzer target: an experiment file must either parse, have its runs planned and every run's
// parameters listed (the first and last few), or throw an fspm::Error naming the problem. The
// process's memory limit is set far below libFuzzer's -malloc_limit_mb, so an allocation the
// limit does not guard (a sweep axis, sampling, the plan) shows up as a fuzzer finding.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "experiments/experiment.hpp"
#include "experiments/run_plan.hpp"
#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fspm::set_memory_limit_bytes(std::size_t{256} << 20);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    // A path in a directory that does not exist, so model files are never read.
    const fspm::experiments::Experiment x = fspm::experiments::parse_experiment(
        std::string_view(reinterpret_cast<const char*>(data), size),
        "/nonexistent-fspm-fuzz/fuzz.toml");
    const fspm::experiments::RunPlan plan(x);
    const std::size_t n = plan.size();
    for (std::size_t i = 0; i < std::min<std::size_t>(n, 4); ++i) plan.run(i);
    for (std::size_t i = n - std::min<std::size_t>(n, 4); i < n; ++i) plan.run(i);
  } catch (const fspm::Error&) {
  }
  return 0;
}
