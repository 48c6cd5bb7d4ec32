#include "fspm/image_request.hpp"

#include <charconv>
#include <string>

#include "fspm/error.hpp"

namespace fspm {

std::string_view view_name(View view) {
  switch (view) {
    case View::kFront:
      return "front";
    case View::kSide:
      return "side";
    case View::kTop:
      return "top";
    case View::kIso:
      return "iso";
  }
  return "front";
}

std::optional<View> find_view(std::string_view name) {
  for (View v : kViews) {
    if (view_name(v) == name) return v;
  }
  return std::nullopt;
}

View view_from_name(std::string_view name) {
  if (const std::optional<View> v = find_view(name)) return *v;
  throw ValueError("unknown view '" + std::string(name) + "' (expected front, side, top or iso)");
}

std::optional<ImageSize> find_image_size(std::string_view text) {
  const auto x = text.find_first_of("xX");
  if (x == std::string_view::npos) return std::nullopt;
  auto number = [](std::string_view s, int& out) {
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && out > 0 && out <= kMaxImageSide;
  };
  ImageSize size;
  if (!number(text.substr(0, x), size.width) || !number(text.substr(x + 1), size.height)) {
    return std::nullopt;
  }
  return size;
}

}  // namespace fspm
