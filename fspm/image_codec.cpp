#include "fspm/image_codec.hpp"

#include <dlfcn.h>

#include <filesystem>
#include <string>
#include <vector>

#include "fspm/error.hpp"

// Where the build and the installation put the module (fspm/CMakeLists.txt).
#ifndef FSPM_IMAGE_CODEC_BUILD_PATH
#define FSPM_IMAGE_CODEC_BUILD_PATH ""
#endif
#ifndef FSPM_IMAGE_CODEC_INSTALL_PATH
#define FSPM_IMAGE_CODEC_INSTALL_PATH ""
#endif
#ifndef FSPM_IMAGE_CODEC_INSTALL_LIBDIR
#define FSPM_IMAGE_CODEC_INSTALL_LIBDIR "lib"
#endif

namespace fspm {
namespace {

constexpr const char* kModuleName = "libfspm_image_codec.so";

// Beside the program or library that holds this code first (bin/../lib in the build tree,
// bin/../LIBDIR once installed, wherever the tree was moved), then the build tree and the
// installation prefix (programs built against an installed fspm), then the loader's own search
// path (LD_LIBRARY_PATH, ld.so.cache).
std::vector<std::string> module_candidates() {
  std::vector<std::string> paths;
  Dl_info self{};
  if (::dladdr(reinterpret_cast<void*>(&module_candidates), &self) != 0 &&
      self.dli_fname != nullptr) {
    const std::filesystem::path dir = std::filesystem::path(self.dli_fname).parent_path();
    for (const char* sub : {"../lib", "../" FSPM_IMAGE_CODEC_INSTALL_LIBDIR, "."}) {
      paths.push_back((dir / sub / kModuleName).lexically_normal().string());
    }
  }
  for (const char* path : {FSPM_IMAGE_CODEC_BUILD_PATH, FSPM_IMAGE_CODEC_INSTALL_PATH}) {
    if (*path != '\0') paths.emplace_back(path);
  }
  paths.emplace_back(kModuleName);
  return paths;
}

const ImageCodecApi* load_codec(std::string& error) {
  error = "not found beside the program, in the build tree or on the library path";
  for (const std::string& path : module_candidates()) {
    if (path.find('/') != std::string::npos && !std::filesystem::exists(path)) continue;
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      error = ::dlerror();
      continue;
    }
    const auto* api = static_cast<const ImageCodecApi*>(::dlsym(handle, "fspm_image_codec_api"));
    if (api != nullptr && api->version == kImageCodecApiVersion) return api;
    error = path + " is not an fspm image codec of this version";
  }
  return nullptr;
}

}  // namespace

const ImageCodecApi& image_codec() {
  static std::string error;
  static const ImageCodecApi* const api = load_codec(error);
  if (api == nullptr) {
    throw ValueError("reading and writing images needs OpenImageIO through " +
                     std::string(kModuleName) +
                     " (built with FSPM_WITH_VTK=ON, installed beside fspm): " + error);
  }
  return *api;
}

std::string image_writer_format(const std::string& path) {
  std::string format;
  return image_codec().writer_format(path, format) ? format : std::string();
}

ImageInfo read_image_info(const std::string& path) {
  ImageInfo info;
  std::string error;
  if (!image_codec().read_info(path, info, error)) {
    throw IoError("cannot read image: " + error, path);
  }
  return info;
}

void read_image_pixels(const std::string& path, int channels, PixelType type, void* out) {
  std::string error;
  if (!image_codec().read_pixels(path, channels, type, out, error)) {
    throw IoError("cannot decode image: " + error, path);
  }
}

std::vector<unsigned char> encode_image(const std::string& path, const ImageInfo& shape,
                                        PixelType type, const void* data) {
  std::vector<unsigned char> bytes;
  std::string error;
  if (!image_codec().encode(path, shape, type, data, bytes, error)) {
    throw IoError("cannot encode image: " + error, path);
  }
  return bytes;
}

}  // namespace fspm
