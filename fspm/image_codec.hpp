#pragma once
// Image decoding and encoding through OpenImageIO, which lives in a module of its own
// (image_codec/, libfspm_image_codec.so) loaded with dlopen the first time an image is read or
// written. OpenImageIO brings about 260 shared libraries whose relocation costs most of a second
// at start-up; programs that link the graphics or crown modules pay it only when they touch an
// image (docs/BENCHMARKS.md, "Start-up").
#include <string>
#include <vector>

namespace fspm {

struct ImageInfo {
  int width = 0;
  int height = 0;
  int channels = 0;
  int bytes_per_value = 0;  // of the values as stored in the file
};

enum class PixelType { kUint8, kFloat };

// The table the module exports as `fspm_image_codec_api` (one toolchain builds both sides, so
// C++ types cross the boundary). Each function returns false and fills `error` on failure.
struct ImageCodecApi {
  int version;
  // The format OpenImageIO writes for the extension of `path` ("png", "openexr"...), or false.
  bool (*writer_format)(const std::string& path, std::string& format);
  bool (*read_info)(const std::string& path, ImageInfo& info, std::string& error);
  // The first `channels` channels of the first subimage, converted to `type` (integers to
  // [0, 1] for kFloat), into `out`, which holds width x height x channels values.
  bool (*read_pixels)(const std::string& path, int channels, PixelType type, void* out,
                      std::string& error);
  // Encodes `data` (width x height x channels values of `type`) in the format of `path`, in
  // memory, into `bytes`.
  bool (*encode)(const std::string& path, const ImageInfo& shape, PixelType type, const void* data,
                 std::vector<unsigned char>& bytes, std::string& error);
};

inline constexpr int kImageCodecApiVersion = 1;

// The loaded module's table. Throws ValueError when the module cannot be found or loaded (fspm
// built without OpenImageIO, or an installation missing libfspm_image_codec.so).
const ImageCodecApi& image_codec();

// The format OpenImageIO writes for `path`'s extension, or "" when it writes none.
std::string image_writer_format(const std::string& path);

// Width, height and channels of the image at `path`; IoError when it cannot be opened.
ImageInfo read_image_info(const std::string& path);

// See ImageCodecApi::read_pixels; IoError when decoding fails.
void read_image_pixels(const std::string& path, int channels, PixelType type, void* out);

// See ImageCodecApi::encode; IoError when encoding fails.
std::vector<unsigned char> encode_image(const std::string& path, const ImageInfo& shape,
                                        PixelType type, const void* data);

}  // namespace fspm
