#include "fspm/error.hpp"

#include "fspm/one_line.hpp"

namespace fspm {
namespace {

std::string format_location(const std::string& message, const std::string& file, int line,
                            int column) {
  std::string out;
  if (!file.empty()) out += file;
  if (line > 0) {
    out += (out.empty() ? "line " : ":") + std::to_string(line);
    if (column > 0) out += ":" + std::to_string(column);
  }
  if (!out.empty()) out += ": ";
  return out + message;
}

// A message quoting a pathological input (a megabyte-long line, a deeply nested value) keeps
// its start and end, so that it still fits on one terminal line or two.
std::string bounded(const std::string& text) {
  if (text.size() <= kMaxErrorMessageLength) return text;
  constexpr std::size_t kTail = 60;
  const std::size_t head = kMaxErrorMessageLength - kTail;
  return text.substr(0, head) + " [... " + std::to_string(text.size() - head - kTail) +
         " characters left out ...] " + text.substr(text.size() - kTail);
}

}  // namespace

Error::Error(const std::string& message, std::string file, int line, int column)
    : std::runtime_error(
          format_location(bounded(one_line(message)), bounded(one_line(file)), line, column)),
      message_(bounded(one_line(message))),
      file_(bounded(one_line(file))),
      line_(line),
      column_(column) {}

}  // namespace fspm
