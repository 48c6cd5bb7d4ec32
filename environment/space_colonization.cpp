#include "environment/space_colonization.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::environment {
namespace {

constexpr std::int64_t kCellBias = 1 << 20;
constexpr std::size_t kMaxMarkers = 10'000'000;

bool has_solids(const Scene& scene) {
  for (const Box& b : scene.boxes) {
    if (b.solid) return true;
  }
  for (const Sphere& s : scene.spheres) {
    if (s.solid) return true;
  }
  for (const TriangleMesh& m : scene.meshes) {
    if (m.solid) return true;
  }
  return false;
}

}  // namespace

void SpaceColonizationParams::validate() const {
  const auto positive = [](double v, const char* name, const char* what) {
    if (!(v > 0 && std::isfinite(v))) {
      throw ValueError(std::string("space colonization ") + name + ": expected a positive " + what);
    }
  };
  positive(marker_density_per_m3, "marker_density_per_m3", "density");
  positive(perception_radius_m, "perception_radius_m", "length");
  positive(occupancy_radius_m, "occupancy_radius_m", "length");
  positive(region_radius_m, "region_radius_m", "length");
  positive(region_height_m, "region_height_m", "length");
  if (!(perception_angle_deg > 0 && perception_angle_deg <= 360)) {
    throw ValueError(
        "space colonization perception_angle_deg: expected an angle in (0, 360] degrees");
  }
}

MarkerField::MarkerField(const SpaceColonizationParams& params, const Scene& scene,
                         const Eigen::Vector3d& base, std::mt19937_64& rng)
    : p_(params), scene_(scene), solids_(has_solids(scene)) {
  p_.validate();
  cos_half_angle_ = std::cos(0.5 * p_.perception_angle_deg * std::numbers::pi / 180.0);
  cell_ = std::max(p_.perception_radius_m, p_.occupancy_radius_m);
  const double r = p_.region_radius_m, h = p_.region_height_m;
  const double expected = p_.marker_density_per_m3 * std::numbers::pi * r * r * h;
  if (!(expected <= kMaxMarkers)) {
    throw ValueError(
        "space colonization: the marker region holds more than 10^7 markers; "
        "lower marker_density_per_m3 or the region");
  }
  // Per marker: its position, the alive flag, the bucket order and key while sorting, the best
  // distance and the owner.
  constexpr double kBytesPerMarker = sizeof(Eigen::Vector3d) + 1 + sizeof(std::uint32_t) +
                                     sizeof(std::pair<std::int64_t, std::uint32_t>) +
                                     sizeof(double) + sizeof(int);
  check_memory(1.1 * expected * kBytesPerMarker,
               "the space-colonization markers (" + std::to_string(std::llround(expected)) + ")");
  const auto count = std::poisson_distribution<std::int64_t>(expected)(rng);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  markers_.reserve(static_cast<std::size_t>(count));
  for (std::int64_t n = 0; n < count; ++n) {
    // Uniform in the disc (sqrt of the radius fraction) and along the height.
    const double rho = r * std::sqrt(u(rng)), phi = 2.0 * std::numbers::pi * u(rng);
    const Eigen::Vector3d m =
        base + Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), h * u(rng));
    if (!scene_.inside_solid(m)) markers_.push_back(m);
  }
  alive_.assign(markers_.size(), 1);
  live_ = markers_.size();
  // Bucket the markers by cell.
  std::vector<std::pair<std::int64_t, std::uint32_t>> keyed(markers_.size());
  for (std::size_t i = 0; i < markers_.size(); ++i) {
    keyed[i] = {cell_key(markers_[i]), static_cast<std::uint32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  order_.resize(keyed.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    order_[i] = keyed[i].second;
    if (i == 0 || keyed[i].first != keyed[i - 1].first) {
      cell_keys_.push_back(keyed[i].first);
      cell_start_.push_back(static_cast<std::uint32_t>(i));
    }
  }
  cell_start_.push_back(static_cast<std::uint32_t>(keyed.size()));
  best_distance_.assign(markers_.size(), 0.0);
  owner_.assign(markers_.size(), -1);
}

std::vector<Eigen::Vector3d> MarkerField::live_marker_positions() const {
  std::vector<Eigen::Vector3d> out;
  out.reserve(live_);
  for (std::size_t i = 0; i < markers_.size(); ++i) {
    if (alive_[i]) out.push_back(markers_[i]);
  }
  return out;
}

std::int64_t MarkerField::cell_key(const Eigen::Vector3d& p) const {
  auto c = [&](double x) {
    const double f = std::floor(x / cell_);
    return static_cast<std::int64_t>(std::clamp(f, -1.0 * (kCellBias - 1), 1.0 * (kCellBias - 1))) +
           kCellBias;
  };
  return (c(p.x()) << 42) | (c(p.y()) << 21) | c(p.z());
}

template <typename Visit>
void MarkerField::for_markers_near(const Eigen::Vector3d& p, Visit&& visit) const {
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const std::int64_t key = cell_key(p + cell_ * Eigen::Vector3d(dx, dy, dz));
        const auto it = std::lower_bound(cell_keys_.begin(), cell_keys_.end(), key);
        if (it == cell_keys_.end() || *it != key) continue;
        const std::size_t c = static_cast<std::size_t>(it - cell_keys_.begin());
        for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          const std::uint32_t m = order_[k];
          if (alive_[m]) visit(m);
        }
      }
    }
  }
}

void MarkerField::occupy(std::span<const Eigen::Vector3d> nodes) {
  const double r2 = p_.occupancy_radius_m * p_.occupancy_radius_m;
  for (const Eigen::Vector3d& n : nodes) {
    for_markers_near(n, [&](std::uint32_t m) {
      if ((markers_[m] - n).squaredNorm() <= r2) {
        alive_[m] = 0;
        --live_;
      }
    });
  }
}

void MarkerField::perceive(std::span<const BudQuery> buds, std::span<BudPerception> out) {
  const double r2 = p_.perception_radius_m * p_.perception_radius_m;
  std::vector<std::uint32_t> touched;
  // 1. Every marker goes to the nearest bud that perceives it (Runions et al. 2007).
  for (std::size_t b = 0; b < buds.size(); ++b) {
    const BudQuery& bud = buds[b];
    for_markers_near(bud.position, [&](std::uint32_t m) {
      const Eigen::Vector3d d = markers_[m] - bud.position;
      const double d2 = d.squaredNorm();
      if (d2 > r2 || d2 < 1e-18 || d.dot(bud.heading) < cos_half_angle_ * std::sqrt(d2)) return;
      if (owner_[m] >= 0 && best_distance_[m] <= d2) return;
      if (solids_ && scene_.segment_blocked(bud.position, markers_[m])) return;
      if (owner_[m] < 0) touched.push_back(m);
      owner_[m] = static_cast<std::int32_t>(b);
      best_distance_[m] = d2;
    });
  }
  // 2. Q and V from the markers each bud owns.
  for (BudPerception& o : out) o = {0.0, Eigen::Vector3d::Zero()};
  std::sort(touched.begin(), touched.end());  // a fixed summation order
  for (std::uint32_t m : touched) {
    BudPerception& o = out[owner_[m]];
    o.light = 1.0;
    o.direction += (markers_[m] - buds[owner_[m]].position).normalized();
    owner_[m] = -1;
  }
  for (BudPerception& o : out) {
    const double n = o.direction.norm();
    o.direction = n > 1e-12 ? Eigen::Vector3d(o.direction / n) : Eigen::Vector3d::UnitZ();
  }
}

}  // namespace fspm::environment
