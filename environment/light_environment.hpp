#pragma once
// Open L-systems (Mech and Prusinkiewicz 1996) answered by the light model: every communication
// module ?E(...) receives ?E(light, dx, dy, dz, inside) at its turtle position: the sky light in
// [0, 1] (Pirk eq. 4.3), the unit mean light direction, and 1 when the position lies inside a
// solid obstacle (else 0). The module's old parameters are replaced by these five.
#include <memory>
#include <span>

#include "environment/light_model.hpp"
#include "lsystem/open_environment.hpp"

namespace fspm::environment {

class LightEnvironment : public lsystem::OpenEnvironment {
 public:
  explicit LightEnvironment(const Scene& scene);
  void respond(std::span<lsystem::EnvironmentQuery> queries) override;
  // Replaces the scene (e.g. with leaf clusters the grammar has grown) before the next step.
  void set_scene(const Scene& scene);
  const LightModel& model() const { return *model_; }

 private:
  std::unique_ptr<LightModel> model_;
};

}  // namespace fspm::environment
