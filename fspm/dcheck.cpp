#include "fspm/dcheck.hpp"

#include <cstdio>
#include <cstdlib>

namespace fspm::detail {

void dcheck_failed(const char* condition, const char* message, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: internal check failed: %s (%s)\n", file, line, condition, message);
  std::fflush(stderr);
  std::abort();
}

}  // namespace fspm::detail
