// The crown's leaves as turbid media as the light of leaf clusters for plastic adaptation: the
// whole crown through a leaf light model of the registry (leaf_light_model.hpp,
// AnalysisParams::canopy_model), in the open for the analysis and again after every step of the
// adaptation that moved or pruned something, with each cluster's cached obstacle visibility.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "environment/leaf_light_model.hpp"
#include "environment/plastic_light.hpp"
#include "environment/sky_distribution.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

class CanopyPlasticLight final : public PlasticLight {
 public:
  // The clusters alone under an open sky through the leaf light model `canopy_model`.
  void analyse(const TreeGraph&, const Scene& open, ClusterLightField&, TreeAnalysis& a) override {
    const std::size_t nc = a.clusters.size();
    const std::vector<Sphere> spheres = cluster_spheres(a.clusters);
    std::vector<LightSample> lit(nc);
    make_leaf_light_model(a.params.canopy_model, open.sky)->evaluate(spheres, {}, lit);
    a.cluster_light.resize(nc);
    a.cluster_direction.resize(nc);
    for (std::size_t c = 0; c < nc; ++c) {
      a.cluster_light[c] = lit[c].light;
      a.cluster_direction[c] = lit[c].direction;
    }
    a.cluster_neighbors.assign(nc, {});
  }

  void start(AdaptationState& s) override;
  void update(AdaptationState& s) override;
  bool relights_crown() const override { return true; }

 private:
  std::unique_ptr<LeafLightModel> canopy_;
  std::vector<Sphere> canopy_spheres_;
  std::vector<std::uint32_t> canopy_index_;
  std::vector<std::span<const float>> canopy_vis_;
  std::vector<LightSample> canopy_out_;
  std::uint64_t lit_epoch_ = ~std::uint64_t{0};  // the adaptation's epoch at the last evaluation
};

void CanopyPlasticLight::start(AdaptationState& s) {
  for (const TreeRun& r : s.runs) {
    if (r.a->params.canopy_model != s.runs.front().a->params.canopy_model) {
      throw ValueError("plastic adaptation: the trees were analysed with different light models");
    }
  }
  const AnalysisParams& params = s.runs.front().a->params;
  Sky sky;
  sky.directions = params.light_directions;
  sky.significance = params.light_significance;
  sky.brightest = s.brightest();
  // A real sky's light per direction (sky_distribution.hpp) instead of the cos^2 sky.
  if (s.scene.sky.distribution) apply_sky_distribution(sky, s.scene.sky.distribution);
  canopy_ = make_leaf_light_model(params.canopy_model, sky);
  if (!s.field.has_obstacles() && s.runs.size() == 1 && !sky.distribution &&
      (s.runs.front().a->brightest - sky.brightest).norm() <= 1e-12) {
    // The analysis' own light: nothing differs from the open scene until something moves.
    const TreeAnalysis& a = *s.runs.front().a;
    for (std::uint32_t c = 0; c < s.field.size(); ++c) {
      s.field.set_light(c, a.cluster_light[c], a.cluster_direction[c]);
    }
    lit_epoch_ = s.epoch;
    return;
  }
  for (std::uint32_t c = 0; c < s.field.size(); ++c) s.field.update_obstacles(c);
  update(s);
}

// Every living cluster's light through the leaf light model, at the clusters' current places,
// with each cluster's cached obstacle visibility (recomputed where it moved enough).
void CanopyPlasticLight::update(AdaptationState& s) {
  if (lit_epoch_ == s.epoch) return;
  canopy_spheres_.clear();
  canopy_index_.clear();
  canopy_vis_.clear();
  bool any_obstacle = false;
  for (std::uint32_t c = 0; c < s.field.size(); ++c) {
    if (!s.field.alive(c)) continue;
    if (s.field.obstacles_stale(c)) s.field.update_obstacles(c);
    const TreeRun& r = s.runs[s.owner[c]];
    const LeafCluster& k = r.a->clusters[c - r.first_cluster];
    canopy_spheres_.push_back({s.field.center(c), k.radius_m, k.translucency, false});
    canopy_index_.push_back(c);
    canopy_vis_.push_back(s.field.obstacle_visibility(c));
    any_obstacle = any_obstacle || !canopy_vis_.back().empty();
  }
  canopy_out_.resize(canopy_spheres_.size());
  canopy_->evaluate(canopy_spheres_,
                    any_obstacle ? std::span<const std::span<const float>>(canopy_vis_)
                                 : std::span<const std::span<const float>>(),
                    canopy_out_);
  for (std::size_t k = 0; k < canopy_index_.size(); ++k) {
    s.field.set_light(canopy_index_[k], canopy_out_[k].light, canopy_out_[k].direction, true);
  }
  ++s.epoch;
  lit_epoch_ = s.epoch;
}

}  // namespace

std::unique_ptr<PlasticLight> make_canopy_plastic_light(const AnalysisParams&) {
  return std::make_unique<CanopyPlasticLight>();
}

}  // namespace fspm::environment
