#include "environment/light_environment.hpp"

namespace fspm::environment {

LightEnvironment::LightEnvironment(const Scene& scene)
    : model_(std::make_unique<LightModel>(scene)) {}

void LightEnvironment::set_scene(const Scene& scene) {
  model_ = std::make_unique<LightModel>(scene);
}

void LightEnvironment::respond(std::span<lsystem::EnvironmentQuery> queries) {
  const Scene& scene = model_->scene();
  for (auto& q : queries) {
    const LightSample s = model_->evaluate(q.position);
    q.parameters = {s.light, s.direction.x(), s.direction.y(), s.direction.z(),
                    scene.inside_solid(q.position) ? 1.0 : 0.0};
  }
}

}  // namespace fspm::environment
