#include "fspm/image_budget.hpp"

#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm {

void check_image_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) {
    throw IoError("cannot read image: no such file", path);
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw IoError("not a regular file (a pipe, device or folder), expected an image file", path);
  }
}

void check_image_size(const std::string& path, std::int64_t width, std::int64_t height,
                      std::int64_t channels, double bytes_per_value) {
  const std::string size = std::to_string(width) + " x " + std::to_string(height) + " pixels";
  if (width < 1 || height < 1 || channels < 1) {
    throw ValueError("the image header declares " + size + " and " + std::to_string(channels) +
                         " channels: no pixels",
                     path);
  }
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  if (pixels > static_cast<double>(kMaxImagePixels)) {
    throw ValueError("the image header declares " + size + ", more than the largest image read (" +
                         std::to_string(kMaxImagePixels) + " pixels, 16384 x 16384)",
                     path);
  }
  check_memory(pixels * static_cast<double>(channels) * bytes_per_value,
               "an image of " + size + " and " + std::to_string(channels) +
                   (channels == 1 ? " channel" : " channels"),
               path);
}

}  // namespace fspm
