// Impostor views and quads of distant plants (Argudo 2014, chapter 6).
#include "graphics/impostor.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

constexpr double kPi = 3.141592653589793;

// The image axes of a view from `toward` (unit) with `up` projected as its up, as glm::lookAt
// builds them: right = up x toward, image up = toward x right. Seen straight along `up`, the
// image's right falls back to `fallback_right`.
void image_axes(const Eigen::Vector3d& toward, const Eigen::Vector3d& up,
                const Eigen::Vector3d& fallback_right, Eigen::Vector3d& right,
                Eigen::Vector3d& image_up) {
  right = up.cross(toward);
  if (right.norm() < 1e-9) right = fallback_right;
  right.normalize();
  image_up = toward.cross(right).normalized();
}

// Four corners of the quad of one instance seen from `toward` (unit, world frame).
void append_quad(const LodScene& scene, std::size_t i,
                 const std::vector<Eigen::Vector3d>& directions, const Eigen::Vector3d& toward,
                 const Eigen::Vector3d& sun, std::vector<ImpostorVertex>& out) {
  const PartPlacement& p = scene.placements[i];
  const BoundingSphere s = placed_sphere(scene.plants[p.part], p);
  const Eigen::Matrix3d linear = p.linear.cast<double>();
  const Eigen::Matrix3d to_plant = linear.inverse();
  const int view = nearest_impostor_view(directions, to_plant * toward);
  const Eigen::Vector3f sun_local = (to_plant * sun).normalized().cast<float>();
  const auto layer =
      static_cast<float>(p.part * directions.size() + static_cast<std::size_t>(view));
  Eigen::Vector3d right, up;
  image_axes(toward, (linear * Eigen::Vector3d::UnitZ()).normalized(),
             (linear * Eigen::Vector3d::UnitX()).normalized(), right, up);
  constexpr int kCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (const auto& c : kCorners) {
    const Eigen::Vector3d x = s.center + s.radius * (c[0] * right + c[1] * up);
    out.push_back(
        {{static_cast<float>(x.x()), static_cast<float>(x.y()), static_cast<float>(x.z())},
         {0.5f * static_cast<float>(c[0] + 1), 0.5f * static_cast<float>(c[1] + 1)},
         layer,
         {sun_local.x(), sun_local.y(), sun_local.z()},
         static_cast<float>(s.radius)});
  }
}

}  // namespace

void ImpostorViews::validate() const {
  if (azimuths < 3) throw ValueError("impostor views: azimuths must be >= 3");
  if (elevations_deg.empty())
    throw ValueError("impostor views: elevations_deg needs at least one elevation");
  for (double e : elevations_deg) {
    if (!(e >= -89.0 && e <= 89.0)) {
      throw ValueError("impostor views: elevations_deg must lie in [-89, 89] degrees");
    }
  }
}

int impostor_view_count(const ImpostorViews& views) {
  return views.azimuths * static_cast<int>(views.elevations_deg.size());
}

Eigen::Vector3d impostor_view_direction(const ImpostorViews& views, int k) {
  const double elevation =
      views.elevations_deg.at(static_cast<std::size_t>(k / views.azimuths)) * kPi / 180.0;
  const double azimuth = 2.0 * kPi * (k % views.azimuths) / views.azimuths;
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
          std::sin(elevation)};
}

std::vector<Eigen::Vector3d> impostor_view_directions(const ImpostorViews& views) {
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < impostor_view_count(views); ++k) {
    out.push_back(impostor_view_direction(views, k));
  }
  return out;
}

int nearest_impostor_view(const ImpostorViews& views, const Eigen::Vector3d& direction) {
  return nearest_impostor_view(impostor_view_directions(views), direction);
}

int nearest_impostor_view(const std::vector<Eigen::Vector3d>& directions,
                          const Eigen::Vector3d& direction) {
  int best = 0;
  double best_cos = -2.0;
  const Eigen::Vector3d d = direction.normalized();
  for (int k = 0; k < static_cast<int>(directions.size()); ++k) {
    const double c = directions[static_cast<std::size_t>(k)].dot(d);
    if (c > best_cos) {
      best_cos = c;
      best = k;
    }
  }
  return best;
}

void append_impostor_quads(const LodScene& scene, const std::vector<InstanceLod>& choice,
                           const ImpostorViews& views, const Eigen::Vector3d& eye_m,
                           const Eigen::Vector3d& sun, std::vector<ImpostorVertex>& out) {
  const std::vector<Eigen::Vector3d> directions = impostor_view_directions(views);
  for (std::size_t i = 0; i < choice.size() && i < scene.placements.size(); ++i) {
    if (!choice[i].visible || !choice[i].impostor) continue;
    const PartPlacement& p = scene.placements[i];
    const Eigen::Vector3d center = placed_sphere(scene.plants[p.part], p).center;
    const Eigen::Vector3d toward = eye_m - center;
    append_quad(
        scene, i, directions,
        toward.norm() > 0.0 ? Eigen::Vector3d(toward.normalized()) : Eigen::Vector3d::UnitX(), sun,
        out);
  }
}

void append_impostor_quads_toward(const LodScene& scene, const std::vector<InstanceLod>& choice,
                                  const ImpostorViews& views, const Eigen::Vector3d& toward,
                                  std::vector<ImpostorVertex>& out) {
  const Eigen::Vector3d unit = toward.normalized();
  const std::vector<Eigen::Vector3d> directions = impostor_view_directions(views);
  for (std::size_t i = 0; i < choice.size() && i < scene.placements.size(); ++i) {
    if (choice[i].visible && choice[i].impostor) append_quad(scene, i, directions, unit, unit, out);
  }
}

}  // namespace fspm::graphics
