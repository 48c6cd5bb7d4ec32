#include "fspm/atomic_file.hpp"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <random>
#include <system_error>

#include "fspm/error.hpp"

namespace fspm {
namespace {

std::string system_reason(int error) {
  return error != 0 ? std::generic_category().message(error) : std::string("write failed");
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.filename().empty()) throw IoError("output path names no file", path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw IoError("cannot write: directory '" + dir.string() + "' does not exist", path);
  }
  // A random suffix keeps concurrent writers (threads, MPI ranks) of the same target apart.
  std::random_device rd;
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict, PR 105651) on chained operator+.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp";
  name += std::to_string(rd() % 1000000);
  const fs::path tmp = dir / name;
  try {
    {
      errno = 0;
      std::ofstream out(tmp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
      if (!out) throw IoError("cannot open for writing: " + system_reason(errno), path);
      out.exceptions(std::ios::badbit);
      try {
        write(out);
        out.close();
      } catch (const std::ios_base::failure&) {
        // A failed write (full disk, file size limit): the reason is still in errno.
        throw IoError("cannot write: " + system_reason(errno), path);
      }
      if (out.fail()) throw IoError("cannot write: " + system_reason(errno), path);
    }
    fs::rename(tmp, target, ec);
    if (ec) throw IoError("cannot replace the file: " + ec.message(), path);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

}  // namespace fspm
