#include "fspm/image_file.hpp"

#include <algorithm>
#include <filesystem>
#include <ostream>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/image_budget.hpp"

namespace fspm {
namespace {

// The header of `path` once the values to read (`channels` of `value_bytes` each per pixel; 0:
// all), the decoder's buffer and the caller's extra bytes fit; `channels` becomes the count read.
ImageInfo checked_header(const std::string& path, int& channels, double value_bytes,
                         double extra_bytes_per_pixel) {
  check_image_file(path);
  const ImageInfo info = read_image_info(path);
  if (channels <= 0) channels = info.channels;
  // Per value read: its own bytes, its share of the decoder's buffer of every stored channel and
  // of the caller's extra bytes.
  const double per_value = value_bytes + (static_cast<double>(info.channels) *
                                              static_cast<double>(info.bytes_per_value) +
                                          extra_bytes_per_pixel) /
                                             static_cast<double>(std::max(channels, 1));
  check_image_size(path, info.width, info.height, channels, per_value);
  return info;
}

template <typename Value>
std::vector<Value> read_values(const std::string& path, int channels, ImageInfo& info,
                               double extra_bytes_per_pixel, PixelType type) {
  info = checked_header(path, channels, sizeof(Value), extra_bytes_per_pixel);
  std::vector<Value> values(static_cast<std::size_t>(info.width) * info.height * channels);
  read_image_pixels(path, channels, type, values.data());
  return values;
}

}  // namespace

void check_image_output(const std::string& path) {
  if (image_writer_format(path).empty()) {
    throw ValueError("unknown image format (expected an extension such as .png, .tif or .exr)",
                     path);
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir)) {
    throw IoError("cannot write: directory '" + dir.string() + "' does not exist", path);
  }
}

std::vector<float> read_image_floats(const std::string& path, int channels, ImageInfo& info,
                                     double extra_bytes_per_pixel) {
  return read_values<float>(path, channels, info, extra_bytes_per_pixel, PixelType::kFloat);
}

std::vector<std::uint8_t> read_image_bytes(const std::string& path, int channels, ImageInfo& info,
                                           double extra_bytes_per_pixel) {
  return read_values<std::uint8_t>(path, channels, info, extra_bytes_per_pixel, PixelType::kUint8);
}

void write_image_file(const std::string& path, const ImageInfo& shape, PixelType type,
                      const void* data) {
  check_image_output(path);
  // Encoded in memory: nothing touches disk until the encoding succeeded.
  const std::vector<unsigned char> bytes = encode_image(path, shape, type, data);
  write_file_atomically(
      path,
      [&](std::ostream& stream) {
        stream.write(reinterpret_cast<const char*>(bytes.data()),
                     static_cast<std::streamsize>(bytes.size()));
      },
      true);
}

}  // namespace fspm
