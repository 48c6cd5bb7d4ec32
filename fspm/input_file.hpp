#pragma once
// Opening and reading input files with errors that say what is wrong with the path: it does not
// exist, is a directory, cannot be read (the system's reason), or is implausibly large (a wrong
// file, /dev/zero), rather than a parser's "file is empty" or "missing key" later on.
#include <cstdint>
#include <istream>
#include <memory>
#include <string>

namespace fspm {

// Largest input read whole into memory (grammars, parameters, scenes, CSV, and tree files that
// come from a pipe or device): far beyond any real one.
inline constexpr std::uint64_t kMaxInputFileBytes = std::uint64_t{1} << 30;
// Largest tree file on disk, streamed rather than read whole: about 100 million nodes.
inline constexpr std::uint64_t kMaxTreeFileBytes = std::uint64_t{16} << 30;

// The whole content of `path`. Throws IoError naming the path: "cannot open: No such file or
// directory" (or the system's other reason), "is a directory, expected a file", or "larger than
// the limit of 1 GiB" when more than `limit` bytes are there. The bytes are kept, so they also
// stay within the memory limit (fspm/memory_budget.hpp): a larger file, or a pipe or device
// that goes on past it, is a MemoryLimitError naming the path and the limit, raised before the
// file is read (a regular file) or as soon as the limit is passed (a pipe or device).
std::string read_input_file(const std::string& path, std::uint64_t limit = kMaxInputFileBytes);

// read_input_file for a text format: a NUL byte (a binary file, /dev/zero) is a ParseError
// "binary data (a NUL byte at byte N), expected a text file", raised at the first read.
std::string read_text_input_file(const std::string& path, std::uint64_t limit = kMaxInputFileBytes);

// A stream over `path` with the same checks: a regular file of at most `limit` bytes is streamed
// from disk, anything else (a pipe, a device) is read whole, at most kMaxInputFileBytes and
// within the memory limit.
std::unique_ptr<std::istream> open_input_file(const std::string& path,
                                              std::uint64_t limit = kMaxInputFileBytes);

}  // namespace fspm
