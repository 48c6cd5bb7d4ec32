#pragma once
// Checks every image reader makes before it allocates: the path is a regular file (a pipe or
// device has no header to trust and cannot be reopened by the decoder), and the size the header
// declares fits a maximum image size and the memory budget (fspm/memory_budget.hpp). A few bytes
// of PNG can declare 20 000 x 20 000 pixels; decoding allocates for the declared size before it
// finds the data missing, so the check must come first.
#include <cstdint>
#include <string>

namespace fspm {

// The largest image read: 2^28 pixels (16384 x 16384), far above a photograph (4000 x 3000 is
// 1.2 x 10^7) or a heightfield of a landscape at 1 m over 16 km.
inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t{1} << 28;

// Throws IoError naming `path`: "cannot read image: no such file" when nothing is there, "not
// a regular file (a pipe, device or folder), expected an image file" when something else is.
void check_image_file(const std::string& path);

// Throws ValueError naming `path` when `width` x `height` is not a positive size or exceeds
// kMaxImagePixels, and MemoryLimitError when decoding `channels` channels of it, at
// `bytes_per_value` bytes per value in all the buffers the reader holds at once, exceeds the
// memory limit.
void check_image_size(const std::string& path, std::int64_t width, std::int64_t height,
                      std::int64_t channels, double bytes_per_value);

}  // namespace fspm
