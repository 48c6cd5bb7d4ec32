#include "environment/points_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <ostream>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/trim.hpp"

namespace fspm::environment {
namespace {

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

std::vector<Eigen::Vector3d> parse_points_csv(std::string_view text, const std::string& file_name) {
  std::vector<Eigen::Vector3d> points;
  int line_no = 0;
  bool header = false;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t nl = text.find('\n', pos);
    const std::string_view raw = text.substr(pos, nl == std::string_view::npos ? nl : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++line_no;
    const std::string_view line = trim(raw);
    if (line.empty() || line.front() == '#') continue;
    const auto fields = split(line);
    if (!header) {
      if (fields.size() != 3 || fields[0] != "x" || fields[1] != "y" || fields[2] != "z") {
        throw ParseError("expected the header x,y,z, got \"" + std::string(line) + "\"", file_name,
                         line_no);
      }
      header = true;
      continue;
    }
    if (fields.size() != 3) {
      throw ParseError("expected 3 comma-separated numbers x,y,z, got " +
                           std::to_string(fields.size()) + " fields",
                       file_name, line_no);
    }
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k) {
      const std::string_view f = fields[k];
      double v = 0.0;
      const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v)) {
        throw ParseError("expected a finite number in column " + std::string(1, "xyz"[k]) +
                             ", got \"" + std::string(f) + "\"",
                         file_name, line_no);
      }
      p[k] = v;
    }
    points.push_back(p);
  }
  if (!header) throw ParseError("expected the header x,y,z (file is empty)", file_name, 1);
  return points;
}

std::vector<Eigen::Vector3d> read_points_csv(const std::string& path) {
  return parse_points_csv(read_text_input_file(path), path);
}

namespace {

// A component of a unit vector below 1e-12 in magnitude is the rounding noise of a sum of terms
// that cancel (a direction in the x-z plane gets dy = -3.2e-18): written as the 0 it is.
double unit_component(double c) { return std::abs(c) < 1e-12 ? 0.0 : c; }

}  // namespace

void write_light_csv(std::ostream& out, std::span<const Eigen::Vector3d> points,
                     std::span<const LightSample> samples) {
  write_light_csv(out, points, samples, {});
}

void write_light_csv(std::ostream& out, std::span<const Eigen::Vector3d> points,
                     std::span<const LightSample> samples,
                     std::span<const DaylightSample> daylight) {
  out << (daylight.empty() ? "x,y,z,light,dx,dy,dz\n"
                           : "x,y,z,light,dx,dy,dz,par_umol_m2_s,daily_par_mol_m2\n");
  char buf[64];
  auto put = [&](double v, char sep) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.write(buf, r.ptr - buf);
    out.put(sep);
  };
  for (std::size_t i = 0; i < points.size() && i < samples.size(); ++i) {
    const bool par = i < daylight.size();
    put(points[i].x(), ',');
    put(points[i].y(), ',');
    put(points[i].z(), ',');
    put(samples[i].light, ',');
    put(unit_component(samples[i].direction.x()), ',');
    put(unit_component(samples[i].direction.y()), ',');
    put(unit_component(samples[i].direction.z()), par ? ',' : '\n');
    if (par) {
      put(daylight[i].par_umol_m2_s, ',');
      put(daylight[i].daily_par_mol_m2, '\n');
    }
  }
}

}  // namespace fspm::environment
