// Palubicki's shadow grid as the light of leaf clusters for plastic adaptation
// (cluster_grid_light.hpp): the analysis fills the grid with the buds of the tree alone in the
// open; the adaptation moves every cluster's buds with its anchor and refills the grid after every
// step that moved or pruned something, each cluster also taking the sky its obstacles hide.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <vector>

#include "environment/cluster_grid_light.hpp"
#include "environment/plastic_light.hpp"

namespace fspm::environment {
namespace {

class ShadowGridPlasticLight final : public PlasticLight {
 public:
  // The clusters' buds alone in the shadow grid of an open scene.
  void analyse(const TreeGraph& t, const Scene& open, ClusterLightField& field,
               TreeAnalysis& a) override {
    const Eigen::Vector3d& sky_direction = field.open_direction();
    const std::size_t nc = a.clusters.size();
    std::vector<Eigen::Vector3d> buds, centers(nc);
    std::vector<std::uint32_t> bud_start;
    cluster_buds(t, a.clusters, buds, bud_start);
    for (std::size_t c = 0; c < nc; ++c) centers[c] = a.clusters[c].center;
    a.cluster_light.assign(nc, 1.0);
    a.cluster_direction.assign(nc, Eigen::Vector3d::UnitZ());
    a.cluster_neighbors.assign(nc, {});
    ClusterGridLight light(a.params.shadow_grid, open);
    light.evaluate(buds, bud_start, centers, std::vector<std::uint8_t>(nc, 1), a.cluster_light,
                   a.cluster_direction);
    for (std::size_t c = 0; c < nc; ++c) {
      combine_sky_and_grid(1.0, sky_direction, a.cluster_light[c], a.cluster_direction[c]);
    }
  }

  void start(AdaptationState& s) override;
  void update(AdaptationState& s) override;
  bool relights_crown() const override { return true; }

 private:
  // Every cluster's buds, as analysed and as moved, refilled into the grid after every step that
  // moved or pruned something.
  std::unique_ptr<ClusterGridLight> grid_;
  std::vector<double> grid_light_;  // the grid's light and direction before the sky's share
  std::vector<Eigen::Vector3d> grid_direction_;
  std::vector<Eigen::Vector3d> buds0_, buds_;
  std::vector<std::uint32_t> bud_start_, bud_cluster_;
  std::uint64_t lit_epoch_ = ~std::uint64_t{0};  // the adaptation's epoch at the last refill
};

void ShadowGridPlasticLight::start(AdaptationState& s) {
  const std::size_t nc = s.field.size();
  bud_start_.assign(1, 0);
  for (TreeRun& r : s.runs) {
    std::vector<Eigen::Vector3d> buds;
    std::vector<std::uint32_t> start;
    cluster_buds(*r.tree, r.a->clusters, buds, start);
    for (std::size_t c = 0; c + 1 < start.size(); ++c) {
      for (std::uint32_t b = start[c]; b < start[c + 1]; ++b) {
        buds0_.push_back(buds[b]);
        bud_cluster_.push_back(static_cast<std::uint32_t>(bud_start_.size() - 1));
      }
      bud_start_.push_back(static_cast<std::uint32_t>(buds0_.size()));
    }
  }
  buds_ = buds0_;
  grid_ = std::make_unique<ClusterGridLight>(s.runs.front().a->params.shadow_grid, s.scene);
  const Eigen::Vector3d brightest = s.brightest();
  if (!s.field.has_obstacles() && s.runs.size() == 1 &&
      (s.runs.front().a->brightest - brightest).norm() <= 1e-12) {
    // The analysis' own light: nothing differs from the open scene until something moves.
    const TreeAnalysis& a = *s.runs.front().a;
    for (std::uint32_t c = 0; c < nc; ++c) {
      s.field.set_light(c, a.cluster_light[c], a.cluster_direction[c]);
    }
    lit_epoch_ = s.epoch;
    return;
  }
  for (std::uint32_t c = 0; c < nc; ++c) s.field.update_obstacles(c);
  update(s);
}

// The buds follow their cluster's anchor; the grid is refilled and every living cluster's light
// read again, unless nothing moved or was pruned since the last time.
void ShadowGridPlasticLight::update(AdaptationState& s) {
  if (lit_epoch_ == s.epoch) return;
  // Only the anchors bent in this step have a new transform (an earlier step's buds were placed
  // at that step's refill: the adaptation changes s.epoch whenever it moves something).
  for (std::size_t b = 0; b < buds_.size(); ++b) {
    const std::uint32_t g = bud_cluster_[b];
    const TreeRun& r = s.runs[s.owner[g]];
    const NodeId anchor = r.a->clusters[g - r.first_cluster].anchor;
    if (r.stamp[anchor] >= 0 && r.stamp[anchor] == s.step) buds_[b] = r.F[anchor](buds0_[b]);
  }
  grid_light_.assign(s.field.lights().begin(), s.field.lights().end());
  grid_direction_.assign(s.field.directions().begin(), s.field.directions().end());
  grid_->evaluate(buds_, bud_start_, s.field.centers(), s.field.alive_flags(), grid_light_,
                  grid_direction_);
  for (std::uint32_t c = 0; c < s.field.size(); ++c) {
    if (!s.field.alive(c)) continue;
    if (s.field.obstacles_stale(c)) s.field.update_obstacles(c);
    Eigen::Vector3d sky_direction;
    const double sky = s.field.sky_light(c, sky_direction);
    combine_sky_and_grid(sky, sky_direction, grid_light_[c], grid_direction_[c]);
    s.field.set_light(c, grid_light_[c], grid_direction_[c], true);
  }
  ++s.epoch;
  lit_epoch_ = s.epoch;
}

}  // namespace

std::unique_ptr<PlasticLight> make_shadow_grid_plastic_light(const AnalysisParams&) {
  return std::make_unique<ShadowGridPlasticLight>();
}

}  // namespace fspm::environment
