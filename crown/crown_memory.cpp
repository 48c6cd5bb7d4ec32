#include "crown/crown_memory.hpp"

#include <algorithm>

#include "fspm/error.hpp"
#include "fspm/image_budget.hpp"
#include "fspm/image_codec.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::crown {
namespace {

// Per pixel of the photograph: its RGB raster (12 bytes), the decoder's floats (4 per channel)
// and the crown, foliage and closing masks (1 byte each). Measured: 17.7 bytes a pixel between a
// 2000 x 1500 and a 4000 x 3000 photograph (peak resident memory).
constexpr double kBytesPerPixel = 12.0 + 3.0;
constexpr double kDecodeBytesPerChannel = 4.0;
// The preview: its three panels (36 bytes), one view (12), its depth buffer (8) and the encoded
// bytes (3); measured 52 bytes a pixel at 4000 x 3000.
constexpr double kPreviewBytesPerPixel = 60.0;
// The side mask, its float copy for writing and the encoded bytes.
constexpr double kSideMaskBytesPerPixel = 6.0;
// Per pixel of the working images: the inflation's sparse system, the base mesh, the relief
// pyramid and the gap filling; measured 45 MB at 512 x 512 over a photograph of 256 x 256.
constexpr double kBytesPerWorkingPixel = 200.0;
// Per cubemap texel: colour, height and radius cubemaps, their strips for writing and the
// texture synthesis; measured 33 bytes a texel at 2048 texels a side.
constexpr double kBytesPerTexel = 40.0;
constexpr int kLargestDefaultCubemap = 256;

}  // namespace

double crown_memory_bytes(const CrownMemoryRequest& r) {
  const double pixels = static_cast<double>(r.width) * static_cast<double>(r.height);
  const double working_side = std::min<double>(r.working_pixels, std::max(r.width, r.height));
  const double texels_side = r.cubemap_size > 0 ? r.cubemap_size : kLargestDefaultCubemap;
  double bytes =
      pixels * (kBytesPerPixel + kDecodeBytesPerChannel * static_cast<double>(r.channels));
  if (r.preview) bytes += pixels * kPreviewBytesPerPixel;
  if (r.side_mask) bytes += pixels * kSideMaskBytesPerPixel;
  bytes += working_side * working_side * kBytesPerWorkingPixel;
  bytes += 6.0 * texels_side * texels_side * kBytesPerTexel;
  return bytes;
}

void check_crown_memory(const std::string& photo, CrownMemoryRequest request,
                        const std::string& mask) {
  check_image_file(photo);
  const ImageInfo info = read_image_info(photo);
  if (!mask.empty()) {
    check_image_file(mask);
    const ImageInfo m = read_image_info(mask);
    check_image_size(mask, m.width, m.height, m.channels,
                     sizeof(float) + static_cast<double>(m.bytes_per_value));
    if (m.width != info.width || m.height != info.height) {
      throw ValueError("the mask is " + std::to_string(m.width) + " x " + std::to_string(m.height) +
                           " pixels but the photograph " + std::to_string(info.width) + " x " +
                           std::to_string(info.height) + ": they must be the same size",
                       mask);
    }
  }
  check_image_size(photo, info.width, info.height, info.channels,
                   sizeof(float) + static_cast<double>(info.bytes_per_value));
  request.width = info.width;
  request.height = info.height;
  request.channels = info.channels;
  std::string what = "the crown of a " + std::to_string(info.width) + " x " +
                     std::to_string(info.height) + " photograph";
  if (request.cubemap_size > 0) {
    what += " with cubemaps of " + std::to_string(request.cubemap_size) + " texels";
  }
  if (request.preview) what += " and its preview";
  check_memory(crown_memory_bytes(request), what, photo);
}

}  // namespace fspm::crown
