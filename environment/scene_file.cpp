#include "environment/scene_file.hpp"

#include <Eigen/Geometry>
#include <numbers>
#include <type_traits>

#include "fspm/scene_reader.hpp"

namespace fspm::environment {
namespace {

constexpr double kDefaultGamma0 = 0.5;  // Pirk 4.3.2

Sky sky_from(const SceneSky& s) {
  Sky sky;
  switch (s.source) {
    case SkySource::kBrightest:
      sky.brightest = s.brightest.normalized();
      break;
    case SkySource::kSun:
      sky.brightest = direction_from_elevation_azimuth(s.sun_elevation_deg, s.sun_azimuth_deg);
      break;
    case SkySource::kNoonSun:
      sky.brightest = noon_sun_direction(s.latitude_deg, static_cast<int>(s.day_of_year));
      break;
    case SkySource::kDefault:
      break;
  }
  sky.directions = s.directions.value_or(sky.directions);
  sky.significance = s.significance.value_or(sky.significance);
  sky.analytic = s.analytic.value_or(sky.analytic);
  return sky;
}

// Adds one obstacle to `scene`, filling in its type's defaults.
class Adder {
 public:
  Adder(const ObstacleSurface& surface, double gamma0, Scene& scene)
      : surface_(surface), gamma0_(gamma0), scene_(scene) {}

  void operator()(const SphereObstacle& o) const {
    Sphere s;
    s.center = o.center;
    s.radius_m = o.radius_m;
    // Pirk eq. 4.4 unless given explicitly.
    s.translucency = surface_.translucency.value_or(
        cluster_translucency(o.radius_m, o.gamma0.value_or(gamma0_)));
    s.solid = surface_.solid.value_or(false);
    scene_.spheres.push_back(s);
  }
  void operator()(const BoxObstacle& o) const {
    Box b;
    b.center = o.center;
    b.half_extent = 0.5 * o.size_m;
    if (o.axis) {
      b.rotation = Eigen::AngleAxisd(o.angle_deg * std::numbers::pi / 180.0, o.axis->normalized())
                       .toRotationMatrix();
    }
    add_box(b);
  }
  void operator()(const WallObstacle& o) const {
    add_box(Box::wall(o.from, o.to, o.base_m, o.height_m, o.thickness_m));
  }
  void operator()(const MeshObstacle& o) const {
    TriangleMesh m;
    m.vertices = o.vertices;
    m.triangles = o.triangles;
    m.translucency = surface_.translucency.value_or(0.0);
    m.solid = surface_.solid.value_or(false);
    m.update_bounds();
    scene_.meshes.push_back(std::move(m));
  }

 private:
  void add_box(Box b) const {
    b.translucency = surface_.translucency.value_or(0.0);
    b.solid = surface_.solid.value_or(true);
    scene_.boxes.push_back(b);
  }

  const ObstacleSurface& surface_;
  double gamma0_;
  Scene& scene_;
};

}  // namespace

Scene scene_from_description(const SceneDescription& description) {
  Scene scene;
  scene.sky = sky_from(description.sky);
  if (description.ground) {
    Ground g;
    g.height_m = description.ground->height_m;
    g.translucency = description.ground->surface.translucency.value_or(0.0);
    g.solid = description.ground->surface.solid.value_or(true);
    scene.ground = g;
  }
  const double gamma0 = description.gamma0.value_or(kDefaultGamma0);
  for (const auto& o : description.obstacles) {
    std::visit(Adder(o.surface, gamma0, scene), o.shape);
  }
  return scene;
}

Scene parse_scene_json(std::string_view text, const std::string& file_name) {
  return scene_from_description(parse_scene_description(text, file_name));
}

Scene read_scene_file(const std::string& path) {
  return scene_from_description(read_scene_description(path));
}

}  // namespace fspm::environment
