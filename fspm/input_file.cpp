#include "fspm/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm {
namespace {

std::string reason(int error) { return std::generic_category().message(error); }

std::string size_text(std::uint64_t bytes) {
  if (bytes >= (std::uint64_t{1} << 30) && bytes % (std::uint64_t{1} << 30) == 0) {
    return std::to_string(bytes >> 30) + " GiB";
  }
  return std::to_string(bytes) + " bytes";
}

[[noreturn]] void too_large(const std::string& path, std::uint64_t limit) {
  throw IoError("larger than the limit of " + size_text(limit) + " for an input file", path);
}

// A file descriptor closed on every path out.
class Descriptor {
 public:
  explicit Descriptor(const std::string& path) : fd_(::open(checked(path), O_RDONLY | O_CLOEXEC)) {
    if (fd_ < 0 && errno == ENOENT) {
      throw FileNotFoundError("cannot open for reading: " + reason(errno), path);
    }
    if (fd_ < 0) throw IoError("cannot open for reading: " + reason(errno), path);
  }
  ~Descriptor() { ::close(fd_); }

  // The path as the system reads it: a NUL byte (possible from Python or a library call) would
  // cut it short and open another file, as Python's own open() refuses it.
  static const char* checked(const std::string& path) {
    if (path.find('\0') != std::string::npos) {
      throw ValueError("the file name holds a NUL byte", path);
    }
    return path.c_str();
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Status of an open file; throws for a directory.
struct stat checked_status(const Descriptor& fd, const std::string& path) {
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw IoError("cannot read: " + reason(errno), path);
  if (S_ISDIR(st.st_mode)) throw IoError("is a directory, expected a file", path);
  return st;
}

// Refuses the first NUL byte of `chunk`, which starts at byte `offset` of the file: a text
// format never holds one, while a binary file or /dev/zero is full of them, so it is told at the
// first read instead of after a gigabyte.
void refuse_binary(std::string_view chunk, std::size_t offset, const std::string& path) {
  const std::size_t at = chunk.find('\0');
  if (at == std::string_view::npos) return;
  throw ParseError(
      "binary data (a NUL byte at byte " + std::to_string(offset + at) + "), expected a text file",
      path);
}

// A pipe or device has no size to check first: its bytes are counted as they come, and refused
// past the memory limit (--memory-limit) as well as past the format's limit.
[[noreturn]] void above_memory_limit(const std::string& path, std::uint64_t memory) {
  throw MemoryLimitError("a pipe or device holding more than the memory limit of " +
                             memory_text(static_cast<double>(memory)) + " (--memory-limit)",
                         path);
}

// The whole content, at most `limit` bytes and within the memory limit: the bytes are kept.
std::string read_all(const Descriptor& fd, const struct stat& st, const std::string& path,
                     std::uint64_t limit, bool text_only = false) {
  std::string text;
  if (S_ISREG(st.st_mode)) {
    if (static_cast<std::uint64_t>(st.st_size) > limit) too_large(path, limit);
    check_memory(static_cast<double>(st.st_size), "reading the whole file", path);
    text.reserve(static_cast<std::size_t>(st.st_size));
  }
  const std::uint64_t memory = memory_limit_bytes();
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw IoError("cannot read: " + reason(errno), path);
    }
    if (text_only) refuse_binary({buffer, static_cast<std::size_t>(n)}, text.size(), path);
    const std::uint64_t total = text.size() + static_cast<std::size_t>(n);
    if (total > limit) too_large(path, limit);
    // A regular file that grows while it is read counts like a pipe.
    if (total > memory) above_memory_limit(path, memory);
    text.append(buffer, static_cast<std::size_t>(n));
  }
  return text;
}

}  // namespace

std::string read_input_file(const std::string& path, std::uint64_t limit) {
  const Descriptor fd(path);
  return read_all(fd, checked_status(fd, path), path, limit);
}

std::string read_text_input_file(const std::string& path, std::uint64_t limit) {
  const Descriptor fd(path);
  return read_all(fd, checked_status(fd, path), path, limit, true);
}

std::unique_ptr<std::istream> open_input_file(const std::string& path, std::uint64_t limit) {
  const Descriptor fd(path);
  const struct stat st = checked_status(fd, path);
  if (!S_ISREG(st.st_mode)) {
    return std::make_unique<std::istringstream>(
        read_all(fd, st, path, std::min(limit, kMaxInputFileBytes)));
  }
  if (static_cast<std::uint64_t>(st.st_size) > limit) too_large(path, limit);
  auto in = std::make_unique<std::ifstream>(path, std::ios::binary);
  if (!*in) throw IoError("cannot open for reading: " + reason(errno), path);
  return in;
}

}  // namespace fspm
