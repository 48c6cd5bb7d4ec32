#pragma once
// The memory a crown reconstruction holds beyond its photograph, estimated from the photograph's
// header before a pixel is decoded (fspm/memory_budget.hpp): the full-resolution photograph and
// its masks, the working images (crown/working_resolution.hpp), the cubemaps and their texture
// synthesis, and the pictures drawn at the photograph's size (preview, side mask). A photograph
// the memory limit cannot hold is refused at once, naming the photograph and the limit.
#include <cstdint>
#include <string>

namespace fspm::crown {

struct CrownMemoryRequest {
  std::int64_t width = 0;   // of the photograph, pixels
  std::int64_t height = 0;  //
  std::int64_t channels = 3;
  int cubemap_size = 0;  // 0: chosen from the crown, at most 256
  int working_pixels = 512;
  bool preview = false;    // front, side and top views at the photograph's size
  bool side_mask = false;  // the side silhouette at the photograph's size
};

// Bytes held at the peak of the reconstruction, an upper estimate.
double crown_memory_bytes(const CrownMemoryRequest& request);

// Reads the header of `photo` and checks it as every image reader does (fspm/image_budget.hpp),
// then checks crown_memory_bytes against the memory limit: throws MemoryLimitError naming
// `photo`, the photograph's size and the limit (--memory-limit). A `mask` (optional) must declare
// the photograph's size: ValueError naming it otherwise, before either is decoded.
void check_crown_memory(const std::string& photo, CrownMemoryRequest request,
                        const std::string& mask = {});

}  // namespace fspm::crown
