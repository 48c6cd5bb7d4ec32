#include "fspm/error.hpp"

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

}  // namespace

Error::Error(const std::string& message, std::string file, int line, int column)
    : std::runtime_error(format_location(message, file, line, column)),
      message_(message),
      file_(std::move(file)),
      line_(line),
      column_(column) {}

}  // namespace fspm
