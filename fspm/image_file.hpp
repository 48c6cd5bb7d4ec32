#pragma once
// Image files in and out through the on-demand OpenImageIO module (fspm/image_codec.hpp), with
// the checks every reader and writer of fspm makes: before decoding, the path is an image file
// and the buffers fit the image-size limit and the memory budget (fspm/image_budget.hpp); before
// writing, the extension names a format and the folder exists; encoded in memory, then written
// atomically (fspm/atomic_file.hpp), so a failed write leaves no file. graphics (renders, height
// and class maps) and crown (photographs, masks, cubemaps) read and write images only here.
#include <cstdint>
#include <string>
#include <vector>

#include "fspm/image_codec.hpp"

namespace fspm {

// Throws ValueError when OpenImageIO writes no format for `path`'s extension, IoError when its
// folder does not exist: the check a command makes before any work.
void check_image_output(const std::string& path);

// The first `channels` channels of the image at `path` (every stored channel when 0), row 0 at
// the top, with `info` set to its header. Before decoding, the values returned, the decoder's
// buffer of the stored ones and `extra_bytes_per_pixel` the caller will hold beside them are
// checked against the memory budget. Floats: 8- and 16-bit integers to [0, 1], float images as
// stored. Throws IoError when the file cannot be read, MemoryLimitError / ValueError when the
// declared size does not fit.
std::vector<float> read_image_floats(const std::string& path, int channels, ImageInfo& info,
                                     double extra_bytes_per_pixel = 0.0);
std::vector<std::uint8_t> read_image_bytes(const std::string& path, int channels, ImageInfo& info,
                                           double extra_bytes_per_pixel = 0.0);

// Encodes `data` (shape.width x shape.height x shape.channels values of `type`, row 0 at the top)
// in the format of `path`'s extension and writes it atomically. Throws like check_image_output,
// and IoError when encoding or writing fails.
void write_image_file(const std::string& path, const ImageInfo& shape, PixelType type,
                      const void* data);

}  // namespace fspm
