#include "cli/gzip.hpp"

#include <zlib.h>

#include "fspm/error.hpp"

namespace fspm::cli {

std::string gzip_compress(std::string_view bytes) {
  z_stream z{};
  // windowBits 15 + 16: the gzip wrapper instead of zlib's own.
  if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw ValueError("gzip: cannot start zlib");
  }
  std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())) + 32, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&z, Z_FINISH);
  const std::size_t written = z.total_out;
  deflateEnd(&z);
  if (status != Z_STREAM_END) throw ValueError("gzip: zlib failed to compress");
  out.resize(written);
  return out;
}

}  // namespace fspm::cli
