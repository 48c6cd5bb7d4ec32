// libFuzzer target: telling a file's kind by its first bytes (fspm/file_kind.hpp) must give a
// kind, or kUnknown, for any bytes, and only the kinds that have a magic or a VTK XML root.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "fspm/file_kind.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const fspm::FileKind kind = fspm::file_kind_by_content(bytes);
  if (kind == fspm::FileKind::kUnknown || kind == fspm::FileKind::kPvd ||
      kind == fspm::FileKind::kVtp) {
    return 0;
  }
  if (!bytes.starts_with(fspm::file_kind_info(kind).magic)) std::abort();
  return 0;
}
