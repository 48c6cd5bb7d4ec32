#pragma once
// LAS point clouds (ASPRS LAS 1.4 R15; uncompressed LAS 1.0-1.4, point data record formats 0-10):
// the public header block gives the version, point format, record length, the number of points
// (the 64-bit count of LAS 1.4 when it is set), scale and offset; every record starts with X, Y,
// Z as int32, and a coordinate is X * scale + offset in double precision. Other fields (intensity,
// classification, colour, ...) are skipped. LAZ (a .laz file, or the compression bits 6-7 of the
// point format byte set) is refused with a ParseError that says to decompress it first.
#include <cstdint>
#include <string>
#include <string_view>

#include "scans/point_set.hpp"

namespace fspm::scans {

struct LasHeader {
  int version_major = 1;
  int version_minor = 2;
  std::uint16_t header_size = 0;
  std::uint32_t point_data_offset = 0;
  int point_format = 0;
  std::uint16_t record_length = 0;
  std::uint64_t points = 0;
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

// The smallest record length of point data record formats 0-10 (LAS 1.4 R15, tables 7-17).
std::uint16_t las_minimum_record_length(int point_format);

// The header of `data`; throws ParseError naming the byte and what was expected for a header that
// is truncated, inconsistent (a record length below its format's, points beyond the file's end,
// a zero scale) or compressed.
LasHeader parse_las_header(std::string_view data, const std::string& path);

PointSet parse_las_points(std::string_view data, const std::string& path);
PointSet read_las_points(const std::string& path);

}  // namespace fspm::scans
