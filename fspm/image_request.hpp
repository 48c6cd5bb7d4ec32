#pragma once
// What a picture of a plant asks for before any renderer is involved: the camera direction and
// the image size. Kept in the core so that experiment files, which know no graphics, hold them
// as types rather than strings (graphics/render.hpp renders them).
#include <optional>
#include <string_view>

namespace fspm {

// Fixed camera directions: "front" looks along +y, "side" along -x, "top" down -z, "iso" from a
// raised corner.
enum class View { kFront, kSide, kTop, kIso };

inline constexpr View kViews[] = {View::kFront, View::kSide, View::kTop, View::kIso};

std::string_view view_name(View view);
// Inverse of view_name; nothing for an unknown name.
std::optional<View> find_view(std::string_view name);
// Inverse of view_name; throws ValueError naming the known views.
View view_from_name(std::string_view name);

// Image sizes of 1..kMaxImageSide pixels per side.
inline constexpr int kMaxImageSide = 16384;

struct ImageSize {
  int width = 0;
  int height = 0;
};

// "WIDTHxHEIGHT" (or "WIDTHXHEIGHT"), each 1..kMaxImageSide; nothing otherwise.
std::optional<ImageSize> find_image_size(std::string_view text);

}  // namespace fspm
