// The encodings the HTML report's trees travel in: base64 against the test vectors of RFC 4648
// section 10, gzip against zlib's own inflate.
#include <gtest/gtest.h>
#include <zlib.h>

#include <random>
#include <string>

#include "cli/base64.hpp"
#include "cli/gzip.hpp"

namespace fspm::cli {
namespace {

TEST(Base64, Rfc4648TestVectors) {
  EXPECT_EQ(base64_encode(""), "");
  EXPECT_EQ(base64_encode("f"), "Zg==");
  EXPECT_EQ(base64_encode("fo"), "Zm8=");
  EXPECT_EQ(base64_encode("foo"), "Zm9v");
  EXPECT_EQ(base64_encode("foob"), "Zm9vYg==");
  EXPECT_EQ(base64_encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64_encode("foobar"), "Zm9vYmFy");
}

TEST(Base64, HighBytesUseTheLastCharacters) {
  // 0xFF 0xFF 0xFF is six bits of 63 four times: "////"; 0xFB 0xEF 0xBE gives "++++".
  EXPECT_EQ(base64_encode(std::string("\xff\xff\xff", 3)), "////");
  EXPECT_EQ(base64_encode(std::string("\xfb\xef\xbe", 3)), "++++");
}

// Inflates gzip data with zlib (windowBits 15 + 16 accepts only the gzip wrapper).
std::string gunzip(const std::string& data, std::size_t size) {
  std::string out(size, '\0');
  z_stream z{};
  EXPECT_EQ(inflateInit2(&z, 15 + 16), Z_OK);
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(inflate(&z, Z_FINISH), Z_STREAM_END);
  out.resize(z.total_out);
  inflateEnd(&z);
  return out;
}

TEST(Gzip, InflatesBackToTheInput) {
  std::mt19937 rng(3);
  std::string bytes(100000, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    // Half random, half repeated: both paths of deflate.
    bytes[i] = i % 2 == 0 ? static_cast<char>(rng() & 0xff) : 'x';
  }
  const std::string packed = gzip_compress(bytes);
  ASSERT_GE(packed.size(), 18u);
  // RFC 1952: magic 1f 8b, method 8 (deflate).
  EXPECT_EQ(static_cast<unsigned char>(packed[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(packed[1]), 0x8b);
  EXPECT_EQ(packed[2], 8);
  EXPECT_LT(packed.size(), bytes.size());
  EXPECT_EQ(gunzip(packed, bytes.size()), bytes);
  EXPECT_EQ(gunzip(gzip_compress(""), 0), "");
}

}  // namespace
}  // namespace fspm::cli
