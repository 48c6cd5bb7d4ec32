#include "graphics/render.hpp"

#include <charconv>
#include <cstdlib>

#include "fspm/error.hpp"

namespace fspm::graphics {

View view_from_name(std::string_view name) {
  if (name == "front") return View::kFront;
  if (name == "side") return View::kSide;
  if (name == "top") return View::kTop;
  if (name == "iso") return View::kIso;
  throw ValueError("unknown view '" + std::string(name) + "' (expected front, side, top or iso)");
}

void parse_size(std::string_view text, int& width, int& height) {
  const auto x = text.find_first_of("xX");
  auto number = [&](std::string_view s, int& out) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && out > 0 && out <= 16384;
  };
  if (x == std::string_view::npos || !number(text.substr(0, x), width) ||
      !number(text.substr(x + 1), height)) {
    throw ValueError("bad image size '" + std::string(text) +
                     "' (expected WIDTHxHEIGHT, e.g. 1024x768, each 1..16384)");
  }
}

}  // namespace fspm::graphics
