// libFuzzer target: telling a file's kind by its first bytes (fspm/file_kind.hpp) must give a
// kind, or kUnknown, for any bytes, and a kind only when the bytes start with its magic (or a
// PCD header entry, or a VTK XML root).
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
  const bool pcd_entry = kind == fspm::FileKind::kPcd && bytes.starts_with("VERSION ");
  if (!pcd_entry && !bytes.starts_with(fspm::file_kind_info(kind).magic)) std::abort();
  return 0;
}
