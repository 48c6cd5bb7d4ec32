// The sky light of leaf clusters for plastic adaptation (Pirk eq. 4.3 at every cluster centre,
// ClusterLightField): the analysis evaluates every cluster once in the open; the adaptation keeps
// that light and evaluates again only the clusters whose surroundings changed enough (Pirk 4.6,
// "the transformations are applied only in the affected areas"): a neighbour in its shadow
// neighbourhood that drifted relative to it by more than kDriftTolerance_m (and kDriftParallax of
// its distance) or vanished, enough to change its light by about kLightChange, a turn of more than
// kTurnTolerance_rad against the sky, or new obstacle visibility.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "environment/plastic_light.hpp"

namespace fspm::environment {
namespace {

// Relative drift that counts, as a share of the distance (about 9 degrees of parallax: half the
// width of one of the 64 sky cells).
constexpr double kDriftParallax = 0.15;
// Possible change of a cluster's light (share of the open sky's) from drifted or vanished
// neighbours before it is re-evaluated: about the resolution of the 64-direction sky (one cell
// near the zenith carries 3 cos^2 / 64 = 4.7 % of the light).
constexpr double kLightChange = 0.05;
// Refreshes with at least 1/kBatchShare of the clusters due use one LightModel for all.
constexpr std::size_t kBatchShare = 8;

class SkyPlasticLight final : public PlasticLight {
 public:
  // The clusters alone under an open sky, one evaluation per cluster, with the neighbour lists
  // the adaptation starts from.
  void analyse(const TreeGraph&, const Scene&, ClusterLightField& field, TreeAnalysis& a) override {
    std::vector<Eigen::Vector3d> centers;
    std::vector<double> radii, gammas;
    for (const LeafCluster& c : a.clusters) {
      centers.push_back(c.center);
      radii.push_back(c.radius_m);
      gammas.push_back(c.translucency);
    }
    field.set_clusters(centers, radii, gammas);
    field.rebuild_grid();
    for (std::uint32_t c = 0; c < a.clusters.size(); ++c) field.evaluate(c);
    a.cluster_light.assign(field.lights().begin(), field.lights().end());
    a.cluster_direction.assign(field.directions().begin(), field.directions().end());
    a.cluster_neighbors = field.take_neighbor_lists();
  }

  void start(AdaptationState& s) override;
  void update(AdaptationState&) override {
    check_moved();
    refresh();
  }

 private:
  void size_clusters(std::size_t nc) {
    eval_q_.assign(nc, Eigen::Quaterniond::Identity());
    dirty_.assign(nc, 0);
    relist_.assign(nc, 0);
    lost_.assign(nc, 0.0);
    eval_path_.assign(nc, 0.0);
    eval_all_path_.assign(nc, 0.0);
    check_.assign(nc, 0);
  }
  void mark_near_other_trees();
  void mark_dirty(std::uint32_t c);
  void mark_evaluated(std::uint32_t c);
  void note_drift(std::uint32_t c, std::uint32_t j, const ClusterNeighbor& e);
  void release_vanished_shade();
  void check_moved();
  void refresh();

  AdaptationState* state_ = nullptr;        // the adaptation start() was given
  std::vector<Eigen::Quaterniond> eval_q_;  // cluster rotation at its last evaluation
  std::vector<std::uint32_t> dirty_list_, check_list_;
  std::vector<std::uint8_t> dirty_, check_, relist_;
  std::vector<double> lost_;
  // Path lengths for the drift bound: per cluster at its evaluation, and the sum of the per-step
  // maxima over all clusters (total and at each cluster's evaluation).
  std::vector<double> eval_path_, eval_all_path_;
  double all_path_ = 0.0;
};

// Sky light (Pirk eq. 4.3): the analysis' light is kept and only what changed against it is
// evaluated again: the sky (everything), obstacles (the clusters they shade), neighbouring trees
// (the clusters within reach of another tree).
void SkyPlasticLight::start(AdaptationState& s) {
  state_ = &s;
  size_clusters(s.field.size());
  bool sky_changed = false;
  const Eigen::Vector3d b = s.brightest();
  for (const TreeRun& r : s.runs) {
    const TreeAnalysis& a = *r.a;
    sky_changed = sky_changed || (a.brightest - b).norm() > 1e-12 ||
                  a.params.light_directions != s.runs.front().a->params.light_directions ||
                  a.params.light_significance != s.runs.front().a->params.light_significance;
    for (std::size_t c = 0; c < a.clusters.size(); ++c) {
      const std::uint32_t g = r.first_cluster + static_cast<std::uint32_t>(c);
      s.field.set_light(g, a.cluster_light[c], a.cluster_direction[c]);
      s.field.share_list(g, &a.cluster_neighbors[c], r.first_cluster);
    }
  }
  const auto nc = static_cast<std::uint32_t>(s.field.size());
  if (sky_changed) {
    for (std::uint32_t c = 0; c < nc; ++c) mark_dirty(c);
  }
  if (s.field.has_obstacles()) {
    for (std::uint32_t c = 0; c < nc; ++c) {
      if (s.field.update_obstacles(c)) mark_dirty(c);
    }
  }
  if (s.runs.size() > 1) mark_near_other_trees();
  refresh();
}

// The clusters within light reach of another tree's box: evaluated again, and their neighbour
// lists, which the analysis made against their own tree only, made again.
void SkyPlasticLight::mark_near_other_trees() {
  AdaptationState& s = *state_;
  const auto nc = static_cast<std::uint32_t>(s.field.size());
  double reach = 0.0;
  for (std::uint32_t c = 0; c < nc; ++c) {
    if (s.field.reach2(c) >= 0.0) reach = std::max(reach, std::sqrt(s.field.reach2(c)));
  }
  reach += ClusterLightField::kListMargin_m;
  std::vector<Eigen::AlignedBox3d> boxes(s.runs.size());
  for (std::uint32_t c = 0; c < nc; ++c) boxes[s.owner[c]].extend(s.center0[c]);
  for (auto& b : boxes) {
    if (!b.isEmpty()) b = Eigen::AlignedBox3d(b.min().array() - reach, b.max().array() + reach);
  }
  for (std::uint32_t c = 0; c < nc; ++c) {
    for (std::size_t k = 0; k < boxes.size(); ++k) {
      if (k != s.owner[c] && boxes[k].contains(s.center0[c])) {
        mark_dirty(c);
        relist_[c] = 1;
      }
    }
  }
}

void SkyPlasticLight::mark_dirty(std::uint32_t c) {
  AdaptationState& s = *state_;
  if (dirty_[c] || !s.field.alive(c)) return;
  dirty_[c] = 1;
  dirty_list_.push_back(c);
}

// A neighbour j that drifted against c by more than the tolerance (and kDriftParallax of its
// distance) may have changed c's light by up to the share it can take (loss_bound); c is
// re-evaluated once these possible changes reach kLightChange.
void SkyPlasticLight::note_drift(std::uint32_t c, std::uint32_t j, const ClusterNeighbor& e) {
  AdaptationState& s = *state_;
  const Eigen::Vector3d now = s.field.center(j) - s.field.center(c);
  const Eigen::Vector3d then = e.relative.cast<double>();
  // Cheap test first: j shades c neither now nor then (out of reach or below the horizon).
  const double r_j = s.field.radius(j), reach2 = s.field.reach2(j);
  if ((now.z() + r_j <= 0.0 || now.squaredNorm() > reach2) &&
      (then.z() + r_j <= 0.0 || then.squaredNorm() > reach2)) {
    return;
  }
  const double dist = then.norm();
  const double tol = std::max(kDriftTolerance_m, kDriftParallax * dist);
  const double drift2 = (now - then).squaredNorm();
  if (drift2 <= tol * tol) return;
  // A cap turned by the angle a changes the integral of I = cos^2 by at most its share times a
  // (|dI/dtheta| <= 1): the light can change by loss_bound * min(1, drift / distance).
  const double turn = dist > 0.0 ? std::min(1.0, std::sqrt(drift2) / dist) : 1.0;
  lost_[c] += turn * std::max(s.field.loss_bound(j, now), s.field.loss_bound(j, then));
  if (lost_[c] >= kLightChange) {
    mark_dirty(c);
  }
}

// A vanished cluster no longer shades the clusters in its shadow volume: they are re-evaluated
// once the light they may have gained since their evaluation reaches kLightChange.
void SkyPlasticLight::release_vanished_shade() {
  AdaptationState& s = *state_;
  for (const std::uint32_t c : s.vanished) {
    const ClusterLightField::ListView view = s.field.neighbors(c);
    for (const ClusterNeighbor& e : view) {
      const std::uint32_t j = e.index + view.offset;
      if (!s.field.alive(j) || dirty_[j]) continue;
      lost_[j] += s.field.loss_bound(c, s.field.center(j) - s.field.center(c));
      if (lost_[j] >= kLightChange) mark_dirty(j);
    }
  }
  s.vanished.clear();
}

// Which clusters' light the moves of this step changed: relative drift against a neighbour that
// moved with another group, a turn against the sky, or new obstacle visibility.
void SkyPlasticLight::check_moved() {
  AdaptationState& s = *state_;
  const double cos_half_turn = std::cos(0.5 * kTurnTolerance_rad);
  // Relative drift since c's evaluation is at most its own path since then plus the largest
  // path any cluster can have made since then (the sum of the per-step maxima): below the
  // tolerance no pair needs a look (small changes, e.g. a box beside the crown, stay cheap).
  all_path_ += s.step_max;
  s.step_max = 0.0;
  const auto may_drift = [&](std::uint32_t c) {
    return (s.path[c] - eval_path_[c]) + (all_path_ - eval_all_path_[c]) > kDriftTolerance_m;
  };
  // The same bound over all clusters at once: when even the worst pair cannot have drifted by
  // the tolerance, no list needs a look.
  double own_max = 0.0, oldest = all_path_;
  for (const std::uint32_t c : s.moved) own_max = std::max(own_max, s.path[c] - eval_path_[c]);
  for (std::uint32_t c = 0; c < s.field.size(); ++c) {
    if (s.field.alive(c)) oldest = std::min(oldest, eval_all_path_[c]);
  }
  const bool any_drift = own_max + (all_path_ - oldest) > kDriftTolerance_m;
  for (const std::uint32_t c : s.moved) {
    if (!s.field.alive(c)) continue;
    if (std::abs(s.anchor_rotation(c).dot(eval_q_[c])) < cos_half_turn) mark_dirty(c);
    if (s.field.obstacles_stale(c) && s.field.update_obstacles(c)) mark_dirty(c);
    if (!any_drift) continue;
    const bool c_may = may_drift(c);
    const ClusterLightField::ListView view = s.field.neighbors(c);
    for (const ClusterNeighbor& e : view) {
      const std::uint32_t j = e.index + view.offset;
      if (!s.field.alive(j) || s.group[j] == s.group[c]) continue;
      if (s.group[j] == kStill && !check_[j] && may_drift(j)) {
        check_[j] = 1;
        check_list_.push_back(j);
      }
      if (c_may && !dirty_[c]) note_drift(c, j, e);
    }
  }
  for (const std::uint32_t c : check_list_) {
    check_[c] = 0;
    if (dirty_[c]) continue;
    const ClusterLightField::ListView view = s.field.neighbors(c);
    for (const ClusterNeighbor& e : view) {
      const std::uint32_t j = e.index + view.offset;
      if (!s.field.alive(j) || s.group[j] == kStill) continue;
      note_drift(c, j, e);
      if (dirty_[c]) break;
    }
  }
  check_list_.clear();
  for (const std::uint32_t c : s.moved) s.group[c] = kStill;
  s.moved.clear();
  release_vanished_shade();
}

void SkyPlasticLight::refresh() {
  AdaptationState& s = *state_;
  if (dirty_list_.empty()) return;
  ++s.epoch;
  std::sort(dirty_list_.begin(), dirty_list_.end());
  // Many due: one LightModel (shadow-volume grid, vectorized caps) for all of them; few: each
  // from its own neighbour list.
  if (dirty_list_.size() * kBatchShare >= s.field.size()) {
    s.field.evaluate_batch(dirty_list_, relist_);
    for (const std::uint32_t c : dirty_list_) mark_evaluated(c);
    dirty_list_.clear();
    return;
  }
  s.field.rebuild_grid();
  for (const std::uint32_t c : dirty_list_) {
    dirty_[c] = 0;
    if (!s.field.alive(c)) continue;
    s.field.evaluate(c, relist_[c] != 0);
    mark_evaluated(c);
  }
  dirty_list_.clear();
}

// Cluster c's light was just evaluated: nothing is due, and the drift and turn bounds restart.
void SkyPlasticLight::mark_evaluated(std::uint32_t c) {
  AdaptationState& s = *state_;
  dirty_[c] = 0;
  relist_[c] = 0;
  eval_q_[c] = s.anchor_rotation(c);
  lost_[c] = 0.0;
  eval_path_[c] = s.path[c];
  eval_all_path_[c] = all_path_;
}

}  // namespace

std::unique_ptr<PlasticLight> make_sky_plastic_light(const AnalysisParams&) {
  return std::make_unique<SkyPlasticLight>();
}

}  // namespace fspm::environment
