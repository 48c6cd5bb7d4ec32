#pragma once
// Gzip (RFC 1952) through zlib: the HTML report's trees travel compressed, and browsers
// decompress them with their built-in DecompressionStream("gzip").
#include <string>
#include <string_view>

namespace fspm::cli {

// Throws ValueError when zlib fails (out of memory).
std::string gzip_compress(std::string_view bytes);

}  // namespace fspm::cli
