#pragma once
// Sets the process's memory limit for one test and restores the default when the test ends, so
// no test leaks its limit into the next.
#include <cstdint>

#include "fspm/memory_budget.hpp"

namespace fspm::test_support {

class ScopedMemoryLimit {
 public:
  explicit ScopedMemoryLimit(std::uint64_t bytes) { set_memory_limit_bytes(bytes); }
  ~ScopedMemoryLimit() { set_memory_limit_bytes(0); }
  ScopedMemoryLimit(const ScopedMemoryLimit&) = delete;
  ScopedMemoryLimit& operator=(const ScopedMemoryLimit&) = delete;
};

}  // namespace fspm::test_support
