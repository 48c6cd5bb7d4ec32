#include "scans/pcd_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "scans/text_lines.hpp"

namespace fspm::scans {
namespace {

struct PcdField {
  std::string name;
  std::size_t size = 4;
  char type = 'F';
  std::size_t count = 1;
};

struct PcdHeader {
  std::vector<PcdField> fields;
  std::size_t points = 0;
  std::string data;
  std::size_t data_offset = 0;
  int data_line = 0;
};

std::size_t to_count(std::string_view s, const std::string& path, int line) {
  constexpr double kMaxCount = 1e12;  // beyond any file; keeps the conversion and sums exact
  const double v = parse_coordinate(s, path, line);
  if (!(v >= 0 && v <= kMaxCount) || v != std::floor(v)) {
    throw ParseError("expected a count from 0 to 10^12, got '" + std::string(s.substr(0, 40)) + "'",
                     path, line);
  }
  return static_cast<std::size_t>(v);
}

void set_column(PcdHeader& h, const std::vector<std::string_view>& f, const std::string& path,
                int line) {
  if (f[0] == "FIELDS") {
    for (std::size_t i = 1; i < f.size(); ++i) h.fields.push_back({std::string(f[i])});
    return;
  }
  if (f.size() != h.fields.size() + 1) {
    throw ParseError("expected one " + std::string(f[0]) + " value per field", path, line);
  }
  for (std::size_t i = 1; i < f.size(); ++i) {
    PcdField& fd = h.fields[i - 1];
    if (f[0] == "SIZE") {
      fd.size = to_count(f[i], path, line);
      if (fd.size != 1 && fd.size != 2 && fd.size != 4 && fd.size != 8) {
        throw ParseError("expected a SIZE of 1, 2, 4 or 8 bytes, got " + std::to_string(fd.size),
                         path, line);
      }
    }
    if (f[0] == "TYPE") fd.type = f[i].empty() ? '?' : f[i][0];
    if (f[0] == "COUNT") fd.count = to_count(f[i], path, line);
  }
}

PcdHeader parse_header(std::string_view data, const std::string& path) {
  TextLines lines(data);
  std::string_view line;
  PcdHeader h;
  while (lines.next(line)) {
    const std::vector<std::string_view> f = split_fields(line);
    if (f.empty() || f[0][0] == '#') continue;
    const int n = lines.line_number();
    if (f[0] == "FIELDS" || f[0] == "SIZE" || f[0] == "TYPE" || f[0] == "COUNT") {
      set_column(h, f, path, n);
    } else if (f[0] == "POINTS" && f.size() == 2) {
      h.points = to_count(f[1], path, n);
    } else if (f[0] == "DATA" && f.size() == 2) {
      h.data = std::string(f[1]);
      h.data_offset = lines.offset();
      h.data_line = n + 1;
      return h;
    } else if (f[0] != "VERSION" && f[0] != "WIDTH" && f[0] != "HEIGHT" && f[0] != "VIEWPOINT") {
      throw ParseError("unknown PCD header line '" + std::string(line.substr(0, 40)) + "'", path,
                       n);
    }
  }
  throw ParseError("the header has no DATA line", path, lines.line_number());
}

double binary_value(const PcdField& f, const char* p) {
  if (f.type == 'F' && f.size == 4)
    return [&] {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }();
  if (f.type == 'F' && f.size == 8)
    return [&] {
      double v;
      std::memcpy(&v, p, 8);
      return v;
    }();
  return std::nan("");
}

void read_binary(const PcdHeader& h, const std::array<int, 3>& col, std::string_view data,
                 const std::string& path, PointSet& out) {
  const std::size_t bytes = data.size() - std::min(h.data_offset, data.size());
  std::size_t stride = 0;
  std::array<std::size_t, 3> at{};
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    for (int c = 0; c < 3; ++c) at[c] = col[c] == static_cast<int>(i) ? stride : at[c];
    stride += h.fields[i].size * h.fields[i].count;  // at most 8 x 10^12 per field
  }
  // Divided, not multiplied: counts from the header cannot overflow the test.
  if (h.points > 0 && (stride == 0 || stride > bytes || h.points > bytes / stride)) {
    throw ParseError("the binary data ends at byte " + std::to_string(data.size()) + ", expected " +
                         std::to_string(h.points) + " points of " + std::to_string(stride) +
                         " bytes from byte " + std::to_string(h.data_offset),
                     path);
  }
  for (std::size_t k = 0; k < h.points; ++k) {
    const char* rec = data.data() + h.data_offset + k * stride;
    Eigen::Vector3d p;
    for (int c = 0; c < 3; ++c) p[c] = binary_value(h.fields[col[c]], rec + at[c]);
    if (!p.allFinite()) {
      throw ParseError("point " + std::to_string(k) + " at byte " +
                           std::to_string(h.data_offset + k * stride) +
                           " is not a finite float x, y, z",
                       path);
    }
    out.points.push_back(p);
  }
}

void read_ascii(const PcdHeader& h, const std::array<int, 3>& col, std::string_view data,
                const std::string& path, PointSet& out) {
  TextLines lines(data, h.data_offset);
  std::string_view line;
  int n = h.data_line - 1;
  while (out.points.size() < h.points && lines.next(line)) {
    ++n;
    const std::vector<std::string_view> f = split_fields(line);
    if (f.empty()) continue;
    if (f.size() < h.fields.size()) {
      throw ParseError("expected " + std::to_string(h.fields.size()) + " values", path, n);
    }
    out.points.emplace_back(parse_coordinate(f[col[0]], path, n),
                            parse_coordinate(f[col[1]], path, n),
                            parse_coordinate(f[col[2]], path, n));
  }
  if (out.points.size() < h.points) {
    throw ParseError("expected " + std::to_string(h.points) + " points, the file ends after " +
                         std::to_string(out.points.size()),
                     path, n);
  }
}

}  // namespace

PointSet parse_pcd_points(std::string_view data, const std::string& path) {
  const PcdHeader h = parse_header(data, path);
  std::array<int, 3> col{-1, -1, -1};
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (h.fields[i].name == std::string(1, static_cast<char>('x' + c))) {
        col[c] = static_cast<int>(i);
      }
    }
  }
  if (col[0] < 0 || col[1] < 0 || col[2] < 0) {
    throw ParseError("FIELDS lacks one of x, y, z", path);
  }
  for (const int c : col) {
    if (h.fields[c].count == 0) {
      throw ParseError("field " + h.fields[c].name + " has COUNT 0, expected at least 1", path);
    }
  }
  PointSet out;
  out.points.reserve(std::min(h.points, data.size() / 2));  // the header's count is not trusted
  if (h.data == "ascii") {
    read_ascii(h, col, data, path, out);
  } else if (h.data == "binary") {
    read_binary(h, col, data, path, out);
  } else {
    throw ParseError("DATA " + h.data + " is not supported, expected ascii or binary", path,
                     h.data_line - 1);
  }
  return out;
}

PointSet read_pcd_points(const std::string& path) {
  return parse_pcd_points(read_input_file(path), path);
}

}  // namespace fspm::scans
