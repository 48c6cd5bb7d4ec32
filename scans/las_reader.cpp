#include "scans/las_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/input_file.hpp"
#include "fspm/memory_budget.hpp"
#include "scans/byte_io.hpp"

namespace fspm::scans {
namespace {

// Public header block sizes (LAS 1.4 R15, table 3 and its 1.2 and 1.3 predecessors).
constexpr std::uint16_t kHeaderSize12 = 227;
constexpr std::uint16_t kHeaderSize13 = 235;
constexpr std::uint16_t kHeaderSize14 = 375;

constexpr std::string_view kDecompress =
    "; decompress it first, e.g. `laszip -i FILE.laz -o FILE.las` or `pdal translate FILE.laz "
    "FILE.las`";

[[noreturn]] void fail(const std::string& message, std::size_t at, const std::string& path) {
  throw ParseError(message + " at byte " + std::to_string(at), path);
}

std::uint16_t minimum_header_size(int minor) {
  if (minor >= 4) return kHeaderSize14;
  return minor == 3 ? kHeaderSize13 : kHeaderSize12;
}

Eigen::Vector3d get_xyz(ByteReader& r, const char* what) {
  Eigen::Vector3d v;
  for (int c = 0; c < 3; ++c) v[c] = r.get<double>(what);
  return v;
}

void check_version(ByteReader& r, LasHeader& h, const std::string& path) {
  r.get_bytes(20, "the file source id, global encoding and GUID");
  h.version_major = r.get<std::uint8_t>("the major version");
  h.version_minor = r.get<std::uint8_t>("the minor version");
  if (h.version_major != 1 || h.version_minor > 4) {
    fail("LAS version " + std::to_string(h.version_major) + "." + std::to_string(h.version_minor) +
             " is not supported, expected 1.0 to 1.4",
         24, path);
  }
  r.get_bytes(68, "the system identifier, generating software and creation date");
  h.header_size = r.get<std::uint16_t>("the header size");
  if (h.header_size < minimum_header_size(h.version_minor)) {
    fail("the header size is " + std::to_string(h.header_size) + ", expected at least " +
             std::to_string(minimum_header_size(h.version_minor)) + " for LAS 1." +
             std::to_string(h.version_minor),
         94, path);
  }
}

void check_point_format(ByteReader& r, LasHeader& h, const std::string& path) {
  const std::uint8_t format = r.get<std::uint8_t>("the point data record format");
  // LASzip marks compressed point data by setting bit 7 (and bit 6) of this byte.
  if (format & 0xC0) {
    fail("the point data is compressed (LAZ, point format byte " + std::to_string(format) + ")" +
             std::string(kDecompress),
         104, path);
  }
  h.point_format = format;
  if (h.point_format > 10) {
    fail("point data record format " + std::to_string(format) + ", expected 0 to 10", 104, path);
  }
  if (h.point_format > 5 && h.version_minor < 4) {
    fail("point data record format " + std::to_string(format) + " needs LAS 1.4, the file is 1." +
             std::to_string(h.version_minor),
         104, path);
  }
  h.record_length = r.get<std::uint16_t>("the point data record length");
  if (h.record_length < las_minimum_record_length(h.point_format)) {
    fail("point records of " + std::to_string(h.record_length) + " bytes, expected at least " +
             std::to_string(las_minimum_record_length(h.point_format)) + " for format " +
             std::to_string(h.point_format),
         105, path);
  }
}

void read_scale_offset(ByteReader& r, LasHeader& h, const std::string& path) {
  h.scale = get_xyz(r, "the scale factors");
  h.offset = get_xyz(r, "the offsets");
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(h.scale[c]) || h.scale[c] == 0.0) {
      fail("the " + std::string(1, static_cast<char>('x' + c)) +
               " scale factor is 0 or not finite, expected e.g. 0.001",
           131 + 8 * static_cast<std::size_t>(c), path);
    }
    if (!std::isfinite(h.offset[c])) {
      fail("the offsets are not finite", 155, path);
    }
  }
}

// The 64-bit count of LAS 1.4 when set; the legacy 32-bit count otherwise. Both set and different
// is an inconsistent header.
void read_point_count(ByteReader& r, LasHeader& h, std::uint32_t legacy, const std::string& path) {
  r.get_bytes(48, "the bounding box");
  h.points = legacy;
  if (h.version_minor < 4) return;
  r.get_bytes(20, "the waveform and extended VLR offsets");
  const std::uint64_t count = r.get<std::uint64_t>("the number of point records");
  if (count != 0 && legacy != 0 && count != legacy) {
    fail("the legacy point count " + std::to_string(legacy) +
             " differs from the LAS 1.4 point count " + std::to_string(count),
         247, path);
  }
  if (count != 0) h.points = count;
}

}  // namespace

std::uint16_t las_minimum_record_length(int point_format) {
  constexpr std::array<std::uint16_t, 11> kLength = {20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};
  return point_format >= 0 && point_format <= 10 ? kLength[static_cast<std::size_t>(point_format)]
                                                 : 0;
}

LasHeader parse_las_header(std::string_view data, const std::string& path) {
  ByteReader r(data, path);
  if (r.get_bytes(std::min<std::size_t>(data.size(), 4), "the signature") != "LASF") {
    fail("not a LAS file, expected it to start with LASF", 0, path);
  }
  LasHeader h;
  check_version(r, h, path);
  h.point_data_offset = r.get<std::uint32_t>("the offset to the point data");
  if (h.point_data_offset < h.header_size) {
    fail("the point data starts at byte " + std::to_string(h.point_data_offset) +
             ", inside the header of " + std::to_string(h.header_size) + " bytes",
         96, path);
  }
  r.get<std::uint32_t>("the number of variable length records");
  check_point_format(r, h, path);
  const std::uint32_t legacy = r.get<std::uint32_t>("the number of point records");
  r.get_bytes(20, "the number of points by return");
  read_scale_offset(r, h, path);
  read_point_count(r, h, legacy, path);
  // Divided, not multiplied: a count from the header cannot overflow the test.
  const std::size_t bytes = data.size() - std::min<std::size_t>(h.point_data_offset, data.size());
  if (h.point_data_offset > data.size() || h.points > bytes / h.record_length) {
    fail("the file ends at byte " + std::to_string(data.size()) + ", expected " +
             std::to_string(h.points) + " point records of " + std::to_string(h.record_length) +
             " bytes from byte " + std::to_string(h.point_data_offset),
         data.size(), path);
  }
  return h;
}

PointSet parse_las_points(std::string_view data, const std::string& path) {
  const LasHeader h = parse_las_header(data, path);
  // The file's bytes are held while the points (3 doubles each) are filled.
  check_memory(static_cast<double>(data.size()) + static_cast<double>(h.points) * 24.0,
               "reading the LAS points", path);
  PointSet out;
  out.points.resize(h.points);
  const char* rec = data.data() + h.point_data_offset;
  for (std::uint64_t k = 0; k < h.points; ++k, rec += h.record_length) {
    std::int32_t xyz[3];
    std::memcpy(xyz, rec, sizeof xyz);  // little-endian, as LAS and the supported platforms
    for (int c = 0; c < 3; ++c) out.points[k][c] = xyz[c] * h.scale[c] + h.offset[c];
  }
  return out;
}

PointSet read_las_points(const std::string& path) {
  // A LAS point set by its kind (fspm/file_kind.hpp), but compressed when named .laz.
  if (table_extension(path) == ".laz") {
    throw ParseError("LAZ (compressed LAS) is not read" + std::string(kDecompress), path);
  }
  return parse_las_points(read_input_file(path), path);
}

}  // namespace fspm::scans
