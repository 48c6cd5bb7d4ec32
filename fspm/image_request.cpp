#include "fspm/image_request.hpp"

#include <algorithm>
#include <charconv>
#include <iterator>
#include <string>

#include "fspm/error.hpp"
#include "fspm/name_table.hpp"

namespace fspm {
namespace {

constexpr NameTable<View, 4> kViewNames{"view",
                                        {{View::kFront, "front", "along +y"},
                                         {View::kSide, "side", "along -x"},
                                         {View::kTop, "top", "down -z"},
                                         {View::kIso, "iso", "from a raised corner"}}};
static_assert(std::size(kViews) == kViewNames.size() &&
                  std::equal(std::begin(kViews), std::end(kViews), kViewNames.values().begin()),
              "every view has its name, in the order of kViews");

}  // namespace

std::string_view view_name(View view) { return kViewNames.name(view); }

std::optional<View> find_view(std::string_view name) { return kViewNames.find(name); }

View view_from_name(std::string_view name) { return kViewNames.from_name(name); }

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
