#include "fspm/scene_obstacle_reader.hpp"

namespace fspm {
namespace {

using nlohmann::json;

ObstacleSurface surface(const JsonFields& f, const json& o, const std::string& path) {
  ObstacleSurface s;
  s.translucency = f.optional_number(o, path, "translucency", 0.0, 1.0, "a translucency in [0, 1]");
  s.solid = f.optional_boolean(o, path, "solid");
  return s;
}

SphereObstacle sphere(const JsonFields& f, const json& o, const std::string& path, bool cluster) {
  f.check_keys(o, path, {"type", "center", "radius", "translucency", "gamma0", "solid"});
  SphereObstacle s;
  s.center = f.vec<3>(o, path, "center");
  s.radius_m = f.number(o, path, "radius", 0, 1e9, "a non-negative radius");
  s.cluster = cluster;
  s.gamma0 = f.optional_number(o, path, "gamma0", 0, 1, "a gamma0 in [0, 1]");
  return s;
}

BoxObstacle box(const JsonFields& f, const json& o, const std::string& path) {
  f.check_keys(
      o, path,
      {"type", "min", "max", "center", "size", "axis", "angle_deg", "translucency", "solid"});
  BoxObstacle b;
  if (o.contains("min") || o.contains("max")) {
    const Eigen::Vector3d lo = f.vec<3>(o, path, "min");
    const Eigen::Vector3d hi = f.vec<3>(o, path, "max");
    if ((hi.array() < lo.array()).any()) f.fail(path + "/max", "max >= min on every axis");
    b.center = 0.5 * (lo + hi);
    b.size_m = hi - lo;
  } else {
    b.center = f.vec<3>(o, path, "center");
    b.size_m = f.vec<3>(o, path, "size");
    if ((b.size_m.array() < 0).any()) f.fail(path + "/size", "non-negative sizes", &o.at("size"));
  }
  if (o.contains("axis") || o.contains("angle_deg")) {
    b.axis = f.vec<3>(o, path, "axis");
    if (b.axis->norm() <= 0) f.fail(path + "/axis", "a non-zero rotation axis", &o.at("axis"));
    b.angle_deg = f.number(o, path, "angle_deg", -360, 360, "an angle in degrees");
  }
  return b;
}

WallObstacle wall(const JsonFields& f, const json& o, const std::string& path) {
  f.check_keys(o, path,
               {"type", "from", "to", "height", "thickness", "base", "translucency", "solid"});
  WallObstacle w;
  w.from = f.vec<2>(o, path, "from");
  w.to = f.vec<2>(o, path, "to");
  w.height_m = f.number(o, path, "height", 0, 1e9, "a non-negative height");
  w.thickness_m = f.optional_number(o, path, "thickness", 0, 1e9, "a non-negative thickness")
                      .value_or(w.thickness_m);
  w.base_m =
      f.optional_number(o, path, "base", -1e9, 1e9, "a base height within 1e9").value_or(0.0);
  return w;
}

MeshObstacle mesh(const JsonFields& f, const json& o, const std::string& path) {
  f.check_keys(o, path, {"type", "vertices", "triangles", "translucency", "solid"});
  MeshObstacle m;
  const std::string pv = path + "/vertices";
  const std::string pt = path + "/triangles";
  if (!o.contains("vertices") || !o.at("vertices").is_array()) {
    f.fail(pv, "an array of [x, y, z] vertices");
  }
  if (!o.contains("triangles") || !o.at("triangles").is_array()) {
    f.fail(pt, "an array of [i, j, k] vertex indices");
  }
  const json& vs = o.at("vertices");
  for (std::size_t i = 0; i < vs.size(); ++i) {
    m.vertices.push_back(f.vec_value<3>(vs[i], pv + "/" + std::to_string(i)));
  }
  const json& ts = o.at("triangles");
  const auto count = static_cast<long long>(m.vertices.size());
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::string p = pt + "/" + std::to_string(i);
    const json& t = ts[i];
    const std::string what = "3 vertex indices below " + std::to_string(count);
    if (!t.is_array() || t.size() != 3) f.fail(p, what, &t);
    Eigen::Vector3i tri;
    for (int k = 0; k < 3; ++k) {
      if (!t[k].is_number_integer() || t[k].get<long long>() < 0 ||
          t[k].get<long long>() >= count) {
        f.fail(p, what, &t);
      }
      tri[k] = t[k].get<int>();
    }
    m.triangles.push_back(tri);
  }
  return m;
}

}  // namespace

SceneGround read_scene_ground(const JsonFields& f, const json& g, const std::string& path) {
  if (!g.is_object()) f.fail(path, "a ground object with z, translucency, solid", &g);
  SceneGround ground;
  ground.height_m = f.optional_number(g, path, "z", -1e9, 1e9, "a height within 1e9").value_or(0.0);
  ground.surface = surface(f, g, path);
  return ground;
}

void read_scene_obstacle(const JsonFields& f, const json& o, const std::string& path,
                         bool allow_ground, SceneDescription& scene) {
  const std::string types = allow_ground ? "sphere, cluster, box, wall, ground, mesh"
                                         : "sphere, cluster, box, wall, mesh";
  if (!o.is_object()) f.fail(path, "an obstacle object", &o);
  if (!o.contains("type") || !o.at("type").is_string()) {
    f.fail(path + "/type", "an obstacle type (" + types + ")",
           o.contains("type") ? &o.at("type") : nullptr);
  }
  const std::string type = o.at("type").get<std::string>();
  if (type == "ground" && allow_ground) {
    f.check_keys(o, path, {"type", "z", "translucency", "solid"});
    if (scene.ground) f.fail(path, "at most one ground plane");
    scene.ground = read_scene_ground(f, o, path);
    return;
  }
  SceneObstacle obstacle;
  if (type == "sphere" || type == "cluster") {
    obstacle.shape = sphere(f, o, path, type == "cluster");
  } else if (type == "box") {
    obstacle.shape = box(f, o, path);
  } else if (type == "wall") {
    obstacle.shape = wall(f, o, path);
  } else if (type == "mesh") {
    obstacle.shape = mesh(f, o, path);
  } else {
    f.fail(path + "/type", "one of " + types, &o.at("type"));
  }
  obstacle.surface = surface(f, o, path);
  scene.obstacles.push_back(std::move(obstacle));
}

}  // namespace fspm
