// Images through OpenImageIO (built with the VTK option, which brings OpenImageIO along).
// Encoded in memory through an IOProxy, then written atomically like every fspm output.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <ostream>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/image_budget.hpp"
#include "graphics/image.hpp"

namespace fspm::graphics {

void check_image_path(const std::string& path) {
  if (!OIIO::ImageOutput::create(path)) {
    throw ValueError("unknown image format for '" + path +
                         "' (expected an extension such as .png, .tif or .exr)",
                     path);
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir)) {
    throw IoError("cannot write: directory '" + dir.string() + "' does not exist", path);
  }
}

void write_image(const Image& image, const std::string& path) {
  if (image.width < 1 || image.height < 1 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw ValueError("image has no pixels or a wrong buffer size", path);
  }
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    throw ValueError("unknown image format for '" + path +
                         "' (expected an extension such as .png, .tif or .exr)",
                     path);
  }
  // PNG and JPEG carry no alpha we need: RGB keeps files small; TIFF/EXR keep RGBA.
  const std::string format = out->format_name();
  const int channels = (format == "png" || format == "jpeg") ? 3 : 4;
  OIIO::ImageSpec spec(image.width, image.height, channels, OIIO::TypeDesc::UINT8);
  std::vector<std::uint8_t> pixels;
  const std::uint8_t* data = image.rgba.data();
  if (channels == 3) {
    pixels.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (std::size_t i = 0, n = pixels.size() / 3; i < n; ++i) {
      for (int c = 0; c < 3; ++c) pixels[3 * i + c] = image.rgba[4 * i + c];
    }
    data = pixels.data();
  }
  if (!out->supports("ioproxy")) {
    throw ValueError("image format '" + format + "' cannot be written atomically here", path);
  }
  OIIO::Filesystem::IOVecOutput memory;  // encode in memory: nothing touches disk yet
  if (!out->set_ioproxy(&memory) || !out->open(path, spec)) {
    throw IoError("cannot encode image: " + out->geterror(), path);
  }
  if (!out->write_image(OIIO::TypeDesc::UINT8, data) || !out->close()) {
    throw IoError("cannot encode image: " + out->geterror(), path);
  }
  const std::vector<unsigned char>& bytes = memory.buffer();
  write_file_atomically(
      path,
      [&](std::ostream& stream) {
        stream.write(reinterpret_cast<const char*>(bytes.data()),
                     static_cast<std::streamsize>(bytes.size()));
      },
      true);
}

Image read_image(const std::string& path) {
  check_image_file(path);
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw IoError("cannot read image: " + OIIO::geterror(), path);
  const OIIO::ImageSpec& spec = in->spec();
  // The stored channels as bytes, the decoder's own buffer of them, and the RGBA copy.
  check_image_size(
      path, spec.width, spec.height, std::max(spec.nchannels, 1),
      1.0 + static_cast<double>(spec.format.size()) + 4.0 / std::max(spec.nchannels, 1));
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  std::vector<std::uint8_t> raw(static_cast<std::size_t>(spec.width) * spec.height *
                                spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, raw.data())) {
    throw IoError("cannot read image: " + in->geterror(), path);
  }
  image.rgba.assign(static_cast<std::size_t>(spec.width) * spec.height * 4, 255);
  for (std::size_t i = 0, n = static_cast<std::size_t>(spec.width) * spec.height; i < n; ++i) {
    for (int c = 0; c < std::min(spec.nchannels, 4); ++c) {
      image.rgba[4 * i + c] = raw[i * spec.nchannels + c];
    }
    if (spec.nchannels < 3) {
      image.rgba[4 * i + 1] = image.rgba[4 * i + 2] = image.rgba[4 * i];
    }
  }
  return image;
}

}  // namespace fspm::graphics
