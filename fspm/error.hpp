#pragma once
// Errors raised for user mistakes (bad files, bad parameters). The library never exits or aborts;
// the CLI turns these into one clear message and exit code 1, Python into exceptions.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace fspm {

// Messages (and file names) longer than this are shortened in the middle.
inline constexpr std::size_t kMaxErrorMessageLength = 300;

// Base of every user-facing error. Carries where the problem is (file, line, column: 0 = unknown)
// and what was expected, so a message can point at the exact spot.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message, std::string file = {}, int line = 0, int column = 0);

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  // The bare message, without the "file:line:column: " prefix that what() carries.
  const std::string& message() const { return message_; }

 private:
  std::string message_;
  std::string file_;
  int line_;
  int column_;
};

// A malformed input text (tree file, Newick string, grammar, TOML, CSV ...).
class ParseError : public Error {
 public:
  using Error::Error;
};

// A file that cannot be opened, read or written.
class IoError : public Error {
 public:
  using Error::Error;
};

// An input file that does not exist (the path, or a folder on it, is missing): an IoError that
// callers can tell apart (Python raises it as a FileNotFoundError).
class FileNotFoundError : public IoError {
 public:
  using IoError::IoError;
};

// A parameter outside its valid range, an unknown name, an impossible request.
class ValueError : public Error {
 public:
  using Error::Error;
};

// A request whose estimated memory is above the memory limit (fspm/memory_budget.hpp), raised
// before anything is allocated.
class MemoryLimitError : public Error {
 public:
  using Error::Error;
};

}  // namespace fspm
