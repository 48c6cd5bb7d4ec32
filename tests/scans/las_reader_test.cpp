// LAS files written byte by byte from the ASPRS LAS 1.4 R15 tables (public header block, table 3;
// point record formats 0-10, tables 7-17), independently of the reader.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "fspm/error.hpp"
#include "scans/las_reader.hpp"
#include "scans/point_set_file.hpp"

namespace fspm::scans {
namespace {

template <class T>
void put(std::string& s, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  s.append(b, sizeof(T));
}

template <class T>
void put_at(std::string& s, std::size_t at, T v) {
  std::memcpy(s.data() + at, &v, sizeof(T));
}

struct LasSpec {
  int minor = 2;
  std::uint8_t format = 0;
  std::uint16_t record_length = 20;
  double scale[3] = {0.001, 0.001, 0.01};
  double offset[3] = {500000.0, 5800000.0, 300.0};
  std::uint32_t vlr_bytes = 0;  // a gap between the header and the point data
  bool legacy_count = true;     // LAS 1.4: also fill the 32-bit count
};

// Header sizes 227 (1.0-1.2), 235 (1.3), 375 (1.4); table 3 offsets written explicitly.
std::string las_file(const LasSpec& sp, const std::vector<std::array<std::int32_t, 3>>& xyz) {
  const std::uint16_t header = sp.minor >= 4 ? 375 : sp.minor == 3 ? 235 : 227;
  std::string s(header, '\0');
  std::memcpy(s.data(), "LASF", 4);
  put_at<std::uint8_t>(s, 24, 1);
  put_at<std::uint8_t>(s, 25, static_cast<std::uint8_t>(sp.minor));
  put_at<std::uint16_t>(s, 94, header);
  put_at<std::uint32_t>(s, 96, header + sp.vlr_bytes);
  put_at<std::uint8_t>(s, 104, sp.format);
  put_at<std::uint16_t>(s, 105, sp.record_length);
  const auto n = static_cast<std::uint32_t>(xyz.size());
  if (sp.minor < 4 || sp.legacy_count) put_at<std::uint32_t>(s, 107, n);
  for (int c = 0; c < 3; ++c) {
    put_at<double>(s, 131 + 8 * static_cast<std::size_t>(c), sp.scale[c]);
    put_at<double>(s, 155 + 8 * static_cast<std::size_t>(c), sp.offset[c]);
  }
  if (sp.minor >= 4) put_at<std::uint64_t>(s, 247, n);
  s.append(sp.vlr_bytes, 'v');
  for (const auto& p : xyz) {
    for (std::int32_t v : p) put(s, v);
    s.append(sp.record_length - 12, '\x7f');  // intensity, returns, class, ... (ignored)
  }
  return s;
}

const std::vector<std::array<std::int32_t, 3>> kRaw = {
    {0, 0, 0}, {1234567, -7654321, 4567}, {-2147483647, 2147483647, -1}};

void expect_points(const PointSet& ps, const LasSpec& sp) {
  ASSERT_EQ(ps.points.size(), kRaw.size());
  for (std::size_t k = 0; k < kRaw.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_DOUBLE_EQ(ps.points[k][c], kRaw[k][c] * sp.scale[c] + sp.offset[c]) << k << " " << c;
    }
  }
}

TEST(LasReader, EveryFormatAndVersionGivesScaledAndOffsetPoints) {
  const int formats[][2] = {{0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 3},  {5, 3},
                            {6, 4}, {7, 4}, {8, 4}, {9, 4}, {10, 4}, {1, 0}};
  const std::uint16_t lengths[] = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  for (const auto& [format, minor] : formats) {
    LasSpec sp;
    sp.minor = minor;
    sp.format = static_cast<std::uint8_t>(format);
    sp.record_length = lengths[format];
    sp.legacy_count = format < 6;
    SCOPED_TRACE("format " + std::to_string(format) + ", LAS 1." + std::to_string(minor));
    expect_points(parse_las_points(las_file(sp, kRaw), "t.las"), sp);
  }
}

TEST(LasReader, ExtraBytesVlrsAndTheMillimetreAtGisCoordinates) {
  LasSpec sp;
  sp.record_length = 20 + 9;  // extra bytes after the format 0 fields
  sp.vlr_bytes = 54 + 10;     // a VLR header and its payload
  const PointSet ps = parse_las_points(las_file(sp, {{1, 2, 3}, {2, 2, 3}}), "t.las");
  expect_points(parse_las_points(las_file(sp, kRaw), "t.las"), sp);
  // One count of the scale apart at x = 500 000 m: still 1 mm apart in double precision.
  EXPECT_NEAR(ps.points[1].x() - ps.points[0].x(), 0.001, 1e-9);
  EXPECT_NEAR(ps.points[0].y(), 5800000.002, 1e-9);
}

TEST(LasReader, HeaderFieldsAndThe14Count) {
  LasSpec sp;
  sp.minor = 4;
  sp.format = 6;
  sp.record_length = 30;
  sp.legacy_count = false;
  const LasHeader h = parse_las_header(las_file(sp, kRaw), "t.las");
  EXPECT_EQ(h.version_minor, 4);
  EXPECT_EQ(h.point_format, 6);
  EXPECT_EQ(h.record_length, 30);
  EXPECT_EQ(h.header_size, 375);
  EXPECT_EQ(h.points, 3u);
  EXPECT_DOUBLE_EQ(h.offset.y(), 5800000.0);
  EXPECT_DOUBLE_EQ(h.scale.z(), 0.01);
}

// Throws a ParseError whose message contains `expected`.
void expect_refused(const std::string& data, const std::string& expected) {
  try {
    (void)parse_las_points(data, "bad.las");
    ADD_FAILURE() << "no error, expected '" << expected << "'";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.las"), std::string::npos) << e.what();
  }
}

TEST(LasReader, TruncatedInconsistentAndCompressedHeadersAreRefused) {
  LasSpec sp;
  const std::string good = las_file(sp, kRaw);
  expect_refused(good.substr(0, 100), "the file ends inside");
  expect_refused(good.substr(0, good.size() - 1), "expected 3 point records of 20 bytes");
  expect_refused("PLY" + good.substr(3), "expected it to start with LASF");
  std::string bad = good;
  put_at<std::uint8_t>(bad, 104, 0x80 | 3);  // LASzip's compression bit
  expect_refused(bad, "laszip");
  bad = good;
  put_at<std::uint16_t>(bad, 105, 19);
  expect_refused(bad, "expected at least 20 for format 0");
  bad = good;
  put_at<std::uint8_t>(bad, 104, 11);
  expect_refused(bad, "expected 0 to 10");
  bad = good;
  put_at<std::uint8_t>(bad, 104, 6);
  expect_refused(bad, "needs LAS 1.4");
  bad = good;
  put_at<double>(bad, 139, 0.0);
  expect_refused(bad, "y scale factor is 0");
  bad = good;
  put_at<std::uint32_t>(bad, 96, 100);
  expect_refused(bad, "inside the header");
  bad = good;
  put_at<std::uint8_t>(bad, 25, 5);
  expect_refused(bad, "expected 1.0 to 1.4");
  LasSpec v13;
  v13.minor = 3;
  bad = las_file(v13, kRaw);
  put_at<std::uint16_t>(bad, 94, 227);
  expect_refused(bad, "expected at least 235");
  LasSpec v14;
  v14.minor = 4;
  bad = las_file(v14, kRaw);
  put_at<std::uint64_t>(bad, 247, 4);
  expect_refused(bad, "differs from the LAS 1.4 point count 4");
  put_at<std::uint64_t>(bad, 247, std::uint64_t{1} << 62);
  put_at<std::uint32_t>(bad, 107, 0);
  expect_refused(bad, "point records of 20 bytes");
}

TEST(LasReader, ReadThroughTheFileDispatchAndLazRefused) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string las = (dir / ("fspm_las_" + std::to_string(::getpid()) + ".LAS")).string();
  const std::string laz = (dir / ("fspm_las_" + std::to_string(::getpid()) + ".laz")).string();
  LasSpec sp;
  std::ofstream(las, std::ios::binary) << las_file(sp, kRaw);
  std::ofstream(laz, std::ios::binary) << las_file(sp, kRaw);
  expect_points(read_point_set(las), sp);
  try {
    (void)read_point_set(laz);
    ADD_FAILURE() << "a .laz file was read";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("decompress"), std::string::npos) << e.what();
  }
  std::filesystem::remove(las);
  std::filesystem::remove(laz);
}

}  // namespace
}  // namespace fspm::scans
