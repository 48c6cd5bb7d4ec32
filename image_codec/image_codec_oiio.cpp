// The OpenImageIO side of fspm/image_codec.hpp, built as a module that fspm loads when it first
// reads or writes an image. It links only OpenImageIO and the standard library.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

#include "fspm/image_codec.hpp"

namespace {

using fspm::ImageInfo;
using fspm::PixelType;

OIIO::TypeDesc type_of(PixelType type) {
  return type == PixelType::kFloat ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
}

bool writer_format(const std::string& path, std::string& format) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) return false;
  format = out->format_name();
  return true;
}

bool read_info(const std::string& path, ImageInfo& info, std::string& error) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    error = OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  info.width = spec.width;
  info.height = spec.height;
  info.channels = spec.nchannels;
  info.bytes_per_value = static_cast<int>(spec.format.size());
  return true;
}

bool read_pixels(const std::string& path, int channels, PixelType type, void* out,
                 std::string& error) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) {
    error = OIIO::geterror();
    return false;
  }
  if (!in->read_image(0, 0, 0, channels, type_of(type), out)) {
    error = in->geterror();
    return false;
  }
  return true;
}

bool encode(const std::string& path, const ImageInfo& shape, PixelType type, const void* data,
            std::vector<unsigned char>& bytes, std::string& error) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    error = "unknown image format";
    return false;
  }
  if (!out->supports("ioproxy")) {
    error = std::string("format '") + out->format_name() + "' cannot be encoded in memory";
    return false;
  }
  OIIO::ImageSpec spec(shape.width, shape.height, shape.channels, type_of(type));
  OIIO::Filesystem::IOVecOutput memory;  // encode in memory: the caller writes atomically
  if (!out->set_ioproxy(&memory) || !out->open(path, spec) ||
      !out->write_image(type_of(type), data) || !out->close()) {
    error = out->geterror();
    return false;
  }
  bytes = memory.buffer();
  return true;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) const fspm::ImageCodecApi fspm_image_codec_api{
    fspm::kImageCodecApiVersion, writer_format, read_info, read_pixels, encode};
