#include "experiments/scene_words.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <variant>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"
#include "fspm/scene_reader.hpp"

namespace fspm::experiments {
namespace {

std::string metres(double v) { return format_significant(v) + " m"; }

// Horizontal distance from (0, 0) to the segment from-to.
double distance_to_segment(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d d = to - from;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp(-from.dot(d) / length2, 0.0, 1.0) : 0.0;
  return (from + t * d).norm();
}

std::string obstacle_words(const SceneObstacle& o) {
  if (const auto* w = std::get_if<WallObstacle>(&o.shape)) {
    return "a wall " + metres(w->height_m) + " high, " + metres(w->thickness_m) + " thick and " +
           metres((w->to - w->from).norm()) + " long, " +
           metres(distance_to_segment(w->from, w->to)) + " from the plant";
  }
  if (const auto* s = std::get_if<SphereObstacle>(&o.shape)) {
    return "a sphere of radius " + metres(s->radius_m) + " centred " +
           metres(s->center.head<2>().norm()) + " from the plant and " + metres(s->center.z()) +
           " up";
  }
  if (const auto* b = std::get_if<BoxObstacle>(&o.shape)) {
    return "a box of " + format_significant(b->size_m.x()) + " x " +
           format_significant(b->size_m.y()) + " x " + metres(b->size_m.z()) + " centred " +
           metres(b->center.head<2>().norm()) + " from the plant";
  }
  const auto& m = std::get<MeshObstacle>(o.shape);
  double nearest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& v : m.vertices) nearest = std::min(nearest, v.head<2>().norm());
  return "a mesh of " + std::to_string(m.triangles.size()) + " triangles, its nearest vertex " +
         metres(nearest) + " from the plant";
}

}  // namespace

std::string scene_in_words(const std::string& scene_path) {
  SceneDescription scene;
  try {
    scene = read_scene_description(scene_path);
  } catch (const Error&) {
    return {};
  }
  std::vector<std::string> parts;
  for (const SceneObstacle& o : scene.obstacles) parts.push_back(obstacle_words(o));
  if (parts.empty()) return {};
  if (scene.ground) parts.push_back("the ground at z = " + metres(scene.ground->height_m));
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i == 0 ? "" : "; ") + parts[i];
  return out;
}

}  // namespace fspm::experiments
