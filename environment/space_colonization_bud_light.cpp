// Space colonization at every bud (Runions et al. 2007, environment/space_colonization.hpp):
// markers scattered once over the crown's space, removed where the tree's nodes occupy them, and
// perceived by the buds in their cones.
#include <memory>
#include <optional>

#include "environment/bud_light.hpp"
#include "environment/space_colonization.hpp"

namespace fspm::environment {
namespace {

class SpaceColonizationBudLight final : public BudLight {
 public:
  explicit SpaceColonizationBudLight(const BudLightContext& context)
      : params_(context.params.space_colonization),
        scene_(context.scene),
        base_(context.base),
        rng_(context.rng) {}

  void sense(const BudLightInput& in, BudLightOutput& out) override {
    // Scattered at the first cycle, from the grower's generator at that point of the growth.
    if (!markers_) markers_.emplace(params_, scene_, base_, rng_);
    occupy(in.metamers);
    queries_.clear();
    query_node_.clear();
    for (std::size_t i = 0; i < in.metamers.size(); ++i) {
      const growth::Metamer& m = in.metamers[i];
      if (!m.alive) continue;
      // Terminal buds look along the shoot, lateral buds along their branching direction.
      if (m.terminal_bud) queries_.push_back({m.end, m.heading});
      if (m.terminal_bud) query_node_.push_back(static_cast<std::int32_t>(i));
      if (m.lateral_bud) queries_.push_back({m.end, m.lateral_dir});
      if (m.lateral_bud) query_node_.push_back(-1 - static_cast<std::int32_t>(i));
    }
    perceptions_.resize(queries_.size());
    markers_->perceive(queries_, perceptions_);
    for (std::size_t k = 0; k < queries_.size(); ++k) {
      const std::int32_t tag = query_node_[k];
      const std::size_t i = static_cast<std::size_t>(tag >= 0 ? tag : -1 - tag);
      (tag >= 0 ? out.q_terminal : out.q_lateral)[i] = perceptions_[k].light;
      (tag >= 0 ? out.dir_terminal : out.dir_lateral)[i] = perceptions_[k].direction;
    }
  }

 private:
  // Markers within the occupancy radius of the tree's nodes are gone (Runions et al. 2007); the
  // nodes born since the last cycle occupy theirs.
  void occupy(std::span<const growth::Metamer> metamers) {
    node_points_.clear();
    for (const growth::Metamer& m : metamers) {
      if (m.alive && m.birth_year >= occupied_year_) node_points_.push_back(m.end);
    }
    occupied_year_ = metamers.empty() ? 0 : metamers.back().birth_year + 1;
    markers_->occupy(node_points_);
  }

  const SpaceColonizationParams& params_;
  const Scene& scene_;
  Eigen::Vector3d base_;
  std::mt19937_64& rng_;
  std::optional<MarkerField> markers_;
  int occupied_year_ = 0;  // nodes born before this year have occupied their markers
  std::vector<Eigen::Vector3d> node_points_;
  std::vector<BudQuery> queries_;
  std::vector<std::int32_t> query_node_;
  std::vector<BudPerception> perceptions_;
};

}  // namespace

std::unique_ptr<BudLight> make_space_colonization_bud_light(const BudLightContext& context) {
  return std::make_unique<SpaceColonizationBudLight>(context);
}

}  // namespace fspm::environment
