// LightModel's closed-form path for points that see boxes (walls). With a_o = 1 - gamma_o and
// Omega_o an occluder's solid angle, the visibility is V = prod_o (1 - a_o [d in Omega_o]).
// For the boxes it is expanded by inclusion-exclusion over the nonempty sets S of boxes,
//   1 - V_boxes = sum_S (-1)^(|S|+1) prod_(k in S) a_k [d in the Omega_k of S],
// each term the cos^2 integral over an intersection of convex spherical polygons, in closed form
// (spherical_polygon.hpp, Arvo 1995); the boxes' part is then exact however they overlap. Sphere
// caps above the horizon enter linearly (analytic_caps.hpp), so the closed form is
//   integral of I m,   m = V_boxes - sum_caps a_c [d in Omega_c],
// and the remainder integral of I (V - m) vanishes unless a cap overlaps another cap or a box, a
// cap crosses the horizon or a mesh is relevant. Only then is the remainder sampled over the
// stratified directions; it is nonzero only in those regions, so large occluders keep their exact
// integral.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "environment/analytic_caps.hpp"
#include "environment/light_model.hpp"
#include "environment/spherical_polygon.hpp"

namespace fspm::environment {

// At most this many boxes are expanded by inclusion-exclusion; beyond, the remainder is sampled.
inline constexpr std::size_t kMaxAnalyticBoxes = 16;
// Inclusion-exclusion visits at most this many polygon intersections before the boxes' overlaps
// are sampled instead.
inline constexpr int kMaxIntersections = 4096;

struct LightModel::Region {
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit
  double cos_a = -1.0;                              // -1: every direction
};

struct LightModel::BoxSky {
  const Box* box = nullptr;
  Region bound;  // the bounding sphere's cap: no ray outside it enters the box
  std::array<SphericalPolygon, 3> face;
  int faces = 0;
};

namespace {

// True when cap i lies above the horizon and overlaps no other cap and no box: its linear term is
// then exact and the remainder vanishes inside it.
template <class Cap, class BoxSky>
bool cap_isolated(std::span<const Cap> caps, std::size_t i, std::span<const BoxSky> boxes) {
  const Cap& c = caps[i];
  if (c.axis.z() < c.sin_a) return false;
  for (std::size_t j = 0; j < caps.size(); ++j) {
    const double cos_sum = c.cos_a * caps[j].cos_a - c.sin_a * caps[j].sin_a;
    if (j != i && c.axis.dot(caps[j].axis) > cos_sum) return false;
  }
  for (const BoxSky& box : boxes) {
    for (int f = 0; f < box.faces; ++f) {
      if (cap_meets_polygon(c.axis, c.cos_a, c.sin_a, box.face[f])) return false;
    }
  }
  return true;
}

// Adds coef * prod a_k * (-1)^(depth) moments of every intersection of `poly` with faces of boxes
// from `first` on (depth-first inclusion-exclusion; empty intersections end a branch). False when
// an intersection overflows or the visit budget runs out.
template <class BoxSky>
bool subtract_intersections(std::span<const BoxSky> boxes, std::size_t first,
                            const SphericalPolygon& poly, double coef, const Eigen::Vector3d& b,
                            AnalyticLight& a, int& budget) {
  for (std::size_t k = first; k < boxes.size(); ++k) {
    const double c = -coef * (1.0 - boxes[k].box->translucency);
    for (int f = 0; f < boxes[k].faces; ++f) {
      if (--budget < 0) return false;
      if (polygons_disjoint(poly, boxes[k].face[f])) continue;
      bool ok = true;
      const SphericalPolygon both = intersect(poly, boxes[k].face[f], ok);
      if (!ok) return false;
      if (both.size == 0) continue;
      const SphericalMoments m = polygon_moments(both, b);
      a.integral -= c * m.integral;
      a.moment -= c * m.moment;
      if (!subtract_intersections(boxes, k + 1, both, c, b, a, budget)) return false;
    }
  }
  return true;
}

// Subtracts the boxes' loss 1 - V_boxes in closed form; false when the overlaps were too many
// (then only the single-box terms, the linear model, are subtracted).
template <class BoxSky>
bool subtract_boxes(std::span<const BoxSky> boxes, const Eigen::Vector3d& b, AnalyticLight& a) {
  int budget = kMaxIntersections;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    const double c = 1.0 - boxes[k].box->translucency;
    for (int f = 0; f < boxes[k].faces; ++f) {
      const SphericalMoments m = polygon_moments(boxes[k].face[f], b);
      a.integral -= c * m.integral;
      a.moment -= c * m.moment;
    }
  }
  if (boxes.size() > kMaxAnalyticBoxes) return false;
  const AnalyticLight linear = a;
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    for (int f = 0; f < boxes[k].faces; ++f) {
      const double c = 1.0 - boxes[k].box->translucency;
      if (!subtract_intersections(boxes, k + 1, boxes[k].face[f], c, b, a, budget)) {
        a = linear;
        return false;
      }
    }
  }
  return true;
}

}  // namespace

bool LightModel::analytic_with_boxes(const Eigen::Vector3d& p, std::span<const Cap> caps,
                                     double all, LightSample& out) const {
  thread_local std::vector<BoxSky> boxes;
  boxes.clear();
  for (std::size_t k = 0; k < scene_.boxes.size(); ++k) {
    if (!box_relevant(k, p)) continue;
    const Box& b = scene_.boxes[k];
    if (b.contains(p)) {
      all *= b.translucency;  // every ray from inside crosses the box
      continue;
    }
    BoxSky sky;
    sky.box = &b;
    const Eigen::Vector3d to = b.center - p;
    const double dist = to.norm(), r = b.bounding_radius();
    if (dist > r) sky.bound = {to / dist, std::sqrt(dist * dist - r * r) / dist};
    sky.faces = box_sky_polygons(b, p, sky.face);
    if (sky.faces > 0) boxes.push_back(sky);
  }
  // Caps crossing the horizon have no closed form over the hemisphere; they are sampled.
  thread_local std::vector<Cap> above;
  above.clear();
  for (const Cap& c : caps) {
    if (c.axis.z() >= c.sin_a) above.push_back(c);
  }
  const Eigen::Vector3d& bright = scene_.sky.brightest;
  // The open sky minus the caps (Pirk eq. 4.3), then minus the boxes.
  AnalyticLight a = analytic_cap_light(bright, std::span<const Cap>(above));
  const std::span<const BoxSky> box_span(boxes);
  const bool boxes_exact = subtract_boxes(box_span, bright, a);
  // Where the remainder V - m can be nonzero: inside caps that are not isolated (with many caps,
  // inside every cap) and relevant meshes.
  thread_local std::vector<Region> regions;
  regions.clear();
  const bool few = caps.size() <= kMaxAnalyticCaps;
  for (std::size_t i = 0; i < caps.size() && few; ++i) {
    if (!cap_isolated(caps, i, box_span)) regions.push_back({caps[i].axis, caps[i].cos_a});
  }
  for (std::size_t k = 0; k < scene_.meshes.size(); ++k) {
    if (!mesh_relevant(k, p)) continue;
    const TriangleMesh& m = scene_.meshes[k];
    const Eigen::Vector3d d = m.center - p;
    const double dist = d.norm(), r = m.bounding_radius_m;
    regions.push_back(dist > r ? Region{d / dist, std::sqrt(dist * dist - r * r) / dist}
                               : Region{Eigen::Vector3d::UnitZ(), -1.0});
  }
  if (!boxes_exact || !fine_few_ || !fine_many_) {
    sample_residual(p, caps, box_span, boxes_exact, a.integral, a.moment);
  } else if (!few || !regions.empty()) {
    sample_fine(few ? *fine_few_ : *fine_many_, p, caps, box_span, !few, regions, a.integral,
                a.moment);
  }
  if (!std::isfinite(a.integral) || !a.moment.allFinite()) return false;
  out.light = std::clamp(all * a.integral / a.open_integral, 0.0, 1.0);
  out.direction = a.moment.norm() > 1e-300 && out.light > 0 ? Eigen::Vector3d(a.moment.normalized())
                                                            : open_direction_;
  return true;
}

// Adds the sampled remainder integral of I (V - m) and its first moment, with m the model of the
// closed form (V_boxes, or 1 - sum_k a_k [d in Omega_k] when the boxes' overlaps were not expanded,
// minus the caps above the horizon), scaled so that the directions' weights integrate the open sky
// exactly (as the sampled path normalizes).
void LightModel::sample_residual(const Eigen::Vector3d& p, std::span<const Cap> caps,
                                 std::span<const BoxSky> boxes, bool boxes_exact, double& integral,
                                 Eigen::Vector3d& moment) const {
  thread_local std::vector<double> vis, linear;
  vis.assign(dirs_.size(), 1.0);
  linear.assign(dirs_.size(), 1.0);
  for (const BoxSky& box : boxes) {
    const Box& b = *box.box;
    const Eigen::Vector3d d = b.center - p;
    const double dist = d.norm();
    const double r = b.bounding_radius();
    auto hit = [&](int i) {
      if (b.ray_entry(p, dirs_.direction(i)) < 0.0) return;
      vis[i] *= b.translucency;
      if (boxes_exact) {
        linear[i] *= b.translucency;
      } else {
        linear[i] -= 1.0 - b.translucency;
      }
    };
    if (dist <= r) {
      for (int i = 0; i < dirs_.size(); ++i) hit(i);
    } else {
      dirs_.for_each_in_cap(d / dist, std::sqrt(dist * dist - r * r) / dist, hit);
    }
  }
  for (const Cap& c : caps) {
    // Caps crossing the horizon have no closed form here (analytic_cap_light integrates the whole
    // cap): they were left out of it and stay out of the linear model.
    const double loss = c.axis.z() >= c.sin_a ? 1.0 - c.gamma : 0.0;
    dirs_.for_each_in_cap(c.axis, c.cos_a, [&](int i) {
      vis[i] *= c.gamma;
      linear[i] -= loss;
    });
  }
  apply_meshes(p, vis);
  double sum = 0.0;
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    const double w = (vis[i] - linear[i]) * weight_[i];
    sum += w;
    m += w * dirs_.direction(i);
  }
  const double scale = weight_sum_ > 0 ? (2.0 * std::numbers::pi / 3.0) / weight_sum_ : 0.0;
  integral += scale * sum;
  moment += scale * m;
}

}  // namespace fspm::environment

namespace fspm::environment {

LightModel::FineSky::FineSky(int count, const Eigen::Vector3d& brightest) : dirs(count) {
  weight.resize(dirs.size());
  for (int i = 0; i < dirs.size(); ++i) {
    const double c = dirs.direction(i).dot(brightest);
    weight[i] = c * c;  // Pirk eq. 4.3
    weight_sum += weight[i];
  }
}

void LightModel::build_fine_directions() {
  const int n = dirs_.size();
  auto count = [&](int refinement) {
    const long long refined = static_cast<long long>(refinement) * n;
    return std::max(n, static_cast<int>(std::min<long long>(refined, kMaxResidualDirections)));
  };
  fine_few_.emplace(count(kFewCapsRefinement), scene_.sky.brightest);
  fine_many_.emplace(count(kManyCapsRefinement), scene_.sky.brightest);
}

// The remainder integral of I (V - m) on the finer directions: every cap is rasterized (product
// of translucencies, sum of the linear losses of the caps above the horizon), then each direction
// inside a cap (`all_caps`) or inside a cap of `cap_regions`, and inside `regions` (meshes), is
// visited once: boxes and meshes are ray-cast there. V = V_boxes prod_c gamma_c V_meshes and
// m = V_boxes - sum_c a_c.
void LightModel::sample_fine(const FineSky& fine, const Eigen::Vector3d& p,
                             std::span<const Cap> caps, std::span<const BoxSky> boxes,
                             bool all_caps, std::span<const Region> regions, double& integral,
                             Eigen::Vector3d& moment) const {
  const HemisphereDirections& dirs = fine.dirs;
  thread_local std::vector<double> prod, loss;
  thread_local std::vector<char> state;  // 0 untouched, 1 in a cap, 2 visited
  thread_local std::vector<int> dirty;
  prod.resize(dirs.size(), 1.0);
  loss.resize(dirs.size(), 0.0);
  state.resize(dirs.size(), 0);
  dirty.clear();
  for (const Cap& c : caps) {
    const double a = c.axis.z() >= c.sin_a ? 1.0 - c.gamma : 0.0;
    dirs.for_each_in_cap(c.axis, c.cos_a, [&](int i) {
      if (state[i] == 0) dirty.push_back(i);
      state[i] = 1;
      prod[i] *= c.gamma;
      loss[i] += a;
    });
  }
  double sum = 0.0;
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  auto visit = [&](int i) {
    if (state[i] == 2) return;
    if (state[i] == 0) dirty.push_back(i);
    state[i] = 2;
    const Eigen::Vector3d& d = dirs.direction(i);
    double v = 1.0;
    for (const BoxSky& box : boxes) {
      if (d.dot(box.bound.axis) >= box.bound.cos_a && box.box->ray_entry(p, d) >= 0.0) {
        v *= box.box->translucency;
      }
    }
    const double model = v - loss[i];
    v *= prod[i];
    for (std::size_t k = 0; k < scene_.meshes.size(); ++k) {
      const int n = mesh_relevant(k, p) ? scene_.meshes[k].crossings(p, d) : 0;
      if (n > 0) v *= std::pow(scene_.meshes[k].translucency, n);
    }
    const double w = (v - model) * fine.weight[i];
    sum += w;
    m += w * d;
  };
  if (all_caps) {
    for (std::size_t k = 0, n = dirty.size(); k < n; ++k) visit(dirty[k]);
  }
  for (const Region& r : regions) {
    if (r.cos_a <= -1.0) {
      for (int i = 0; i < dirs.size(); ++i) visit(i);
    } else {
      dirs.for_each_in_cap(r.axis, r.cos_a, visit);
    }
  }
  for (const int i : dirty) {
    prod[i] = 1.0;
    loss[i] = 0.0;
    state[i] = 0;
  }
  const double scale = fine.weight_sum > 0 ? (2.0 * std::numbers::pi / 3.0) / fine.weight_sum : 0.0;
  integral += scale * sum;
  moment += scale * m;
}

}  // namespace fspm::environment
