// Sky light at every bud: the sky hemisphere shaded by the obstacles and by every live shoot's
// leaf cluster, the bud's own cluster left out (Pirk eq. 4.3, environment/light_model.hpp).
#include <memory>

#include "environment/bud_light.hpp"
#include "environment/light_model.hpp"

namespace fspm::environment {
namespace {

class SkyBudLight final : public BudLight {
 public:
  bool needs_cluster_scene() const override { return true; }

  void sense(const BudLightInput& in, BudLightOutput& out) override {
    const LightModel light(*in.cluster_scene);
    for (std::size_t i = 0; i < in.metamers.size(); ++i) {
      const growth::Metamer& m = in.metamers[i];
      if (!growth::has_bud(m)) continue;
      const std::int32_t own = in.shoots[m.shoot].sphere;
      const LightSample s =
          light.evaluate(m.end, own < 0 ? kNoSphere : static_cast<std::uint32_t>(own));
      out.q_terminal[i] = out.q_lateral[i] = s.light;
      out.dir_terminal[i] = out.dir_lateral[i] = s.direction;
    }
  }
};

}  // namespace

std::unique_ptr<BudLight> make_sky_bud_light(const BudLightContext&) {
  return std::make_unique<SkyBudLight>();
}

}  // namespace fspm::environment
