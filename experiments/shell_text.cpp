#include "experiments/shell_text.hpp"

namespace fspm::experiments {
namespace {

bool kept_in_file_name(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '-' || c == '_' || c == '+';
}

}  // namespace

std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string file_stem_from_name(const std::string& name) {
  std::string out;
  out.reserve(name.size());
  for (char c : name) out += kept_in_file_name(c) ? c : '_';
  if (out.empty()) return "experiment";
  if (out.front() == '.' || out.front() == '-') out.front() = '_';
  return out;
}

}  // namespace fspm::experiments
