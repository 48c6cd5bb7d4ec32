#include "environment/scene_file.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/nesting_depth.hpp"

namespace fspm::environment {
namespace {

using nlohmann::json;

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& path, const std::string& expected,
                         const json* got = nullptr) const {
    std::string msg = (path.empty() ? std::string("/") : path) + ": expected " + expected;
    if (got) msg += ", got " + got->dump();
    throw ValueError(msg, file_);
  }

  void check_keys(const json& obj, const std::string& path,
                  std::initializer_list<const char*> allowed) const {
    std::set<std::string> ok(allowed.begin(), allowed.end());
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      if (!ok.count(it.key())) {
        std::string list;
        for (const auto& k : ok) list += (list.empty() ? "" : ", ") + k;
        fail(path + "/" + it.key(), "one of the keys " + list + " (unknown key)");
      }
    }
  }

  double number(const json& obj, const std::string& path, const char* key, double lo, double hi,
                const std::string& what) const {
    const std::string p = path + "/" + key;
    if (!obj.contains(key)) fail(p, what + " (missing)");
    const json& v = obj.at(key);
    if (!v.is_number()) fail(p, what, &v);
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < lo || x > hi) fail(p, what, &v);
    return x;
  }
  double number_or(const json& obj, const std::string& path, const char* key, double fallback,
                   double lo, double hi, const std::string& what) const {
    return obj.contains(key) ? number(obj, path, key, lo, hi, what) : fallback;
  }
  bool boolean_or(const json& obj, const std::string& path, const char* key, bool fallback) const {
    if (!obj.contains(key)) return fallback;
    if (!obj.at(key).is_boolean()) fail(path + "/" + key, "true or false", &obj.at(key));
    return obj.at(key).get<bool>();
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vec(const json& obj, const std::string& path, const char* key) const {
    const std::string p = path + "/" + key;
    const std::string what = "an array of " + std::to_string(N) + " numbers within 1e9";
    if (!obj.contains(key)) fail(p, what + " (missing)");
    return vec_value<N>(obj.at(key), p);
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vec_value(const json& v, const std::string& p) const {
    const std::string what = "an array of " + std::to_string(N) + " numbers within 1e9";
    if (!v.is_array() || v.size() != N) fail(p, what, &v);
    Eigen::Matrix<double, N, 1> out;
    for (int i = 0; i < N; ++i) {
      // Coordinates beyond 1e9 m are surely mistakes and would overflow the spatial index.
      if (!v[i].is_number() || !(std::abs(v[i].get<double>()) <= 1e9)) fail(p, what, &v);
      out[i] = v[i].get<double>();
    }
    return out;
  }
  double translucency(const json& obj, const std::string& path, double fallback) const {
    return number_or(obj, path, "translucency", fallback, 0.0, 1.0, "a translucency in [0, 1]");
  }

  Sky sky(const json& s, const std::string& path) const {
    if (!s.is_object()) fail(path, "an object", &s);
    check_keys(s, path,
               {"model", "brightest", "sun", "latitude_deg", "day_of_year", "directions",
                "significance", "analytic"});
    Sky sky;
    if (s.contains("model") && s.at("model") != "cos2") {
      fail(path + "/model", "\"cos2\"", &s.at("model"));
    }
    int sources = s.contains("brightest") + s.contains("sun") + s.contains("latitude_deg");
    if (sources > 1) fail(path, "only one of brightest, sun, latitude_deg");
    if (s.contains("brightest")) {
      const Eigen::Vector3d b = vec<3>(s, path, "brightest");
      if (b.norm() <= 0.0) fail(path + "/brightest", "a non-zero vector", &s.at("brightest"));
      sky.brightest = b.normalized();
    } else if (s.contains("sun")) {
      const json& sun = s.at("sun");
      const std::string p = path + "/sun";
      if (!sun.is_object()) fail(p, "an object with elevation_deg and azimuth_deg", &sun);
      check_keys(sun, p, {"elevation_deg", "azimuth_deg"});
      sky.brightest = direction_from_elevation_azimuth(
          number(sun, p, "elevation_deg", -90, 90, "an elevation in [-90, 90] degrees"),
          number(sun, p, "azimuth_deg", -360, 360, "an azimuth in [-360, 360] degrees"));
    } else if (s.contains("latitude_deg")) {
      const double lat = number(s, path, "latitude_deg", -90, 90, "a latitude in [-90, 90]");
      const double day = number(s, path, "day_of_year", 1, 366, "a day of year in [1, 366]");
      sky.brightest = noon_sun_direction(lat, static_cast<int>(day));
    } else if (s.contains("day_of_year")) {
      fail(path + "/latitude_deg", "a latitude to go with day_of_year (missing)");
    }
    sky.directions = static_cast<int>(
        number_or(s, path, "directions", 256, 1, 1 << 20, "a direction count in [1, 1048576]"));
    sky.significance =
        number_or(s, path, "significance", sky.significance, 0, 0.999, "a number in [0, 1)");
    sky.analytic = boolean_or(s, path, "analytic", true);
    return sky;
  }

  void occluder(const json& o, const std::string& path, double gamma0, Scene& scene) const {
    if (!o.is_object()) fail(path, "an occluder object", &o);
    if (!o.contains("type") || !o.at("type").is_string()) {
      fail(path + "/type", "an occluder type (sphere, cluster, box, wall, ground, mesh)",
           o.contains("type") ? &o.at("type") : nullptr);
    }
    const std::string type = o.at("type").get<std::string>();
    if (type == "sphere" || type == "cluster") {
      check_keys(o, path, {"type", "center", "radius", "translucency", "gamma0", "solid"});
      Sphere s;
      s.center = vec<3>(o, path, "center");
      s.radius_m = number(o, path, "radius", 0, 1e9, "a non-negative radius");
      const double g0 = number_or(o, path, "gamma0", gamma0, 0, 1, "a gamma0 in [0, 1]");
      // Pirk eq. 4.4 unless given explicitly.
      s.translucency = translucency(o, path, cluster_translucency(s.radius_m, g0));
      s.solid = boolean_or(o, path, "solid", false);
      scene.spheres.push_back(s);
    } else if (type == "box") {
      check_keys(
          o, path,
          {"type", "min", "max", "center", "size", "axis", "angle_deg", "translucency", "solid"});
      Box b;
      if (o.contains("min") || o.contains("max")) {
        const Eigen::Vector3d lo = vec<3>(o, path, "min");
        const Eigen::Vector3d hi = vec<3>(o, path, "max");
        if ((hi.array() < lo.array()).any()) fail(path + "/max", "max >= min on every axis");
        b = Box::from_min_max(lo, hi);
      } else {
        b.center = vec<3>(o, path, "center");
        const Eigen::Vector3d size = vec<3>(o, path, "size");
        if ((size.array() < 0).any()) fail(path + "/size", "non-negative sizes", &o.at("size"));
        b.half_extent = 0.5 * size;
      }
      if (o.contains("axis") || o.contains("angle_deg")) {
        const Eigen::Vector3d axis = vec<3>(o, path, "axis");
        if (axis.norm() <= 0) fail(path + "/axis", "a non-zero rotation axis", &o.at("axis"));
        const double angle = number(o, path, "angle_deg", -360, 360, "an angle in degrees");
        b.rotation = Eigen::AngleAxisd(angle * std::numbers::pi / 180.0, axis.normalized())
                         .toRotationMatrix();
      }
      b.translucency = translucency(o, path, 0.0);
      b.solid = boolean_or(o, path, "solid", true);
      scene.boxes.push_back(b);
    } else if (type == "wall") {
      check_keys(o, path,
                 {"type", "from", "to", "height", "thickness", "base", "translucency", "solid"});
      const Eigen::Vector2d from = vec<2>(o, path, "from");
      const Eigen::Vector2d to = vec<2>(o, path, "to");
      const double height = number(o, path, "height", 0, 1e9, "a non-negative height");
      const double thickness =
          number_or(o, path, "thickness", 0.2, 0, 1e9, "a non-negative thickness");
      const double base = number_or(o, path, "base", 0.0, -1e9, 1e9, "a base height within 1e9");
      Box b = Box::wall(from, to, base, height, thickness);
      b.translucency = translucency(o, path, 0.0);
      b.solid = boolean_or(o, path, "solid", true);
      scene.boxes.push_back(b);
    } else if (type == "ground") {
      check_keys(o, path, {"type", "z", "translucency", "solid"});
      if (scene.ground) fail(path, "at most one ground plane");
      Ground g;
      g.height_m = number_or(o, path, "z", 0.0, -1e9, 1e9, "a height within 1e9");
      g.translucency = translucency(o, path, 0.0);
      g.solid = boolean_or(o, path, "solid", true);
      scene.ground = g;
    } else if (type == "mesh") {
      check_keys(o, path, {"type", "vertices", "triangles", "translucency", "solid"});
      TriangleMesh m;
      const std::string pv = path + "/vertices";
      const std::string pt = path + "/triangles";
      if (!o.contains("vertices") || !o.at("vertices").is_array()) {
        fail(pv, "an array of [x, y, z] vertices");
      }
      if (!o.contains("triangles") || !o.at("triangles").is_array()) {
        fail(pt, "an array of [i, j, k] vertex indices");
      }
      const json& vs = o.at("vertices");
      for (std::size_t i = 0; i < vs.size(); ++i) {
        m.vertices.push_back(vec_value<3>(vs[i], pv + "/" + std::to_string(i)));
      }
      const json& ts = o.at("triangles");
      for (std::size_t i = 0; i < ts.size(); ++i) {
        const std::string p = pt + "/" + std::to_string(i);
        const json& t = ts[i];
        const std::string what = "3 vertex indices below " + std::to_string(m.vertices.size());
        if (!t.is_array() || t.size() != 3) fail(p, what, &t);
        Eigen::Vector3i tri;
        for (int k = 0; k < 3; ++k) {
          if (!t[k].is_number_integer() || t[k].get<long long>() < 0 ||
              t[k].get<long long>() >= static_cast<long long>(m.vertices.size())) {
            fail(p, what, &t);
          }
          tri[k] = t[k].get<int>();
        }
        m.triangles.push_back(tri);
      }
      m.translucency = translucency(o, path, 0.0);
      m.solid = boolean_or(o, path, "solid", false);
      m.update_bounds();
      scene.meshes.push_back(std::move(m));
    } else {
      fail(path + "/type", "one of sphere, cluster, box, wall, ground, mesh", &o.at("type"));
    }
  }

 private:
  std::string file_;
};

}  // namespace

Scene parse_scene_json(std::string_view text, const std::string& file_name) {
  check_json_depth(text, file_name);
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    // Turn the byte offset into line and column.
    int line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string what = e.what();
    const auto pos = what.find("syntax error");
    throw ParseError(
        "expected valid JSON (" + (pos == std::string::npos ? what : what.substr(pos)) + ")",
        file_name, line, column);
  } catch (const json::exception& e) {
    // Out-of-range numbers and the like, which nlohmann reports without a position.
    throw ParseError(std::string("expected valid JSON (") + e.what() + ")", file_name);
  }
  Reader r(file_name);
  if (!doc.is_object()) r.fail("", "a JSON object with sky and occluders", &doc);
  r.check_keys(doc, "", {"sky", "occluders", "gamma0"});
  Scene scene;
  if (doc.contains("sky")) scene.sky = r.sky(doc.at("sky"), "/sky");
  const double gamma0 =
      r.number_or(doc, "", "gamma0", 0.5, 0.0, 1.0, "a base cluster translucency in [0, 1]");
  if (doc.contains("occluders")) {
    const json& occ = doc.at("occluders");
    if (!occ.is_array()) r.fail("/occluders", "an array of occluders", &occ);
    for (std::size_t i = 0; i < occ.size(); ++i) {
      r.occluder(occ[i], "/occluders/" + std::to_string(i), gamma0, scene);
    }
  }
  return scene;
}

Scene read_scene_file(const std::string& path) {
  return parse_scene_json(read_input_file(path), path);
}

}  // namespace fspm::environment
