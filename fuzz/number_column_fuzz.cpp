// libFuzzer target: the sample reader of `fspm stats` must either return numbers or throw
// fspm::Error. The first byte picks one-number-per-line or a CSV column named "x".
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fspm/error.hpp"
#include "fspm/number_column.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view column = (data[0] & 1) != 0 ? "x" : "";
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    for (const double v : fspm::parse_number_column(text, "fuzz", column)) {
      if (!std::isfinite(v)) std::abort();  // the reader promises finite numbers only
    }
  } catch (const fspm::Error&) {
  }
  return 0;
}
