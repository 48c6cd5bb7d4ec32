// Palubicki's shadow grid at every bud (environment/shadow_grid.hpp): the buds and the obstacles
// cast shade pyramids into a voxel grid over the buds, refilled every cycle.
#include <memory>

#include "environment/bud_light.hpp"
#include "environment/shadow_grid.hpp"

namespace fspm::environment {
namespace {

class ShadowGridBudLight final : public BudLight {
 public:
  explicit ShadowGridBudLight(const BudLightContext& context)
      : scene_(context.scene), grid_(context.params.shadow_grid) {
    // Under a real sky the pyramids lean along its mean direction, so shade falls away from the
    // sun.
    if (context.params.site_sky) grid_.set_light_direction(context.scene.sky.brightest);
  }

  void sense(const BudLightInput& in, BudLightOutput& out) override {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const growth::Metamer& m : in.metamers) {
      if (!growth::has_bud(m)) continue;
      lo = lo.cwiseMin(m.end);
      hi = hi.cwiseMax(m.end);
    }
    if (lo.x() > hi.x()) return;
    grid_.reset(lo, hi);
    grid_.add_obstacles(scene_);
    for (const growth::Metamer& m : in.metamers) {
      if (growth::has_bud(m))
        grid_.add_bud(m.end, (m.terminal_bud ? 1.0 : 0.0) + (m.lateral_bud ? 1.0 : 0.0));
    }
    grid_.propagate();
    for (std::size_t i = 0; i < in.metamers.size(); ++i) {
      if (!growth::has_bud(in.metamers[i])) continue;
      out.q_terminal[i] = out.q_lateral[i] = grid_.bud_light(in.metamers[i].end);
      out.dir_terminal[i] = out.dir_lateral[i] = grid_.growth_direction(in.metamers[i].end);
    }
  }

 private:
  const Scene& scene_;
  ShadowGrid grid_;
};

}  // namespace

std::unique_ptr<BudLight> make_shadow_grid_bud_light(const BudLightContext& context) {
  return std::make_unique<ShadowGridBudLight>(context);
}

}  // namespace fspm::environment
