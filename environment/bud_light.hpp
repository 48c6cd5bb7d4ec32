#pragma once
// The bud light models of the growth model (Palubicki et al. 2009, step 1): each gives every live
// bud its light Q and optimal growth direction V. One file per model (`sky_bud_light.cpp`,
// `shadow_grid_bud_light.cpp`, `space_colonization_bud_light.cpp`), created through the registry
// of light models shared with plastic adaptation (kLightModels, light_model_registry.hpp) from the
// `BudLightModel` a parameter file names.
#include <Eigen/Core>
#include <memory>
#include <random>
#include <span>
#include <vector>

#include "environment/growth_metamer.hpp"
#include "environment/growth_params.hpp"
#include "environment/scene.hpp"

namespace fspm::environment {

// What a model is made from, once per grown tree.
struct BudLightContext {
  const GrowthParams& params;
  const Scene& scene;  // obstacles, ground and sky (its brightest direction set from a real sky)
  Eigen::Vector3d base;
  std::mt19937_64& rng;  // the grower's generator, drawn from in the order of the growth
};

// What a model reads each cycle: the tree so far and, for models that ask for it, the scene with
// every live shoot's leaf cluster as a sphere (Shoot::sphere its index).
struct BudLightInput {
  std::span<const growth::Metamer> metamers;
  std::span<const growth::Shoot> shoots;
  const Scene* cluster_scene = nullptr;
};

// What it writes, per metamer (sized to the metamers, zero light and +z already): the light and
// direction of the terminal and of the lateral bud.
struct BudLightOutput {
  std::vector<double>& q_terminal;
  std::vector<double>& q_lateral;
  std::vector<Eigen::Vector3d>& dir_terminal;
  std::vector<Eigen::Vector3d>& dir_lateral;
};

class BudLight {
 public:
  virtual ~BudLight() = default;
  // True when sense() reads BudLightInput::cluster_scene.
  virtual bool needs_cluster_scene() const { return false; }
  virtual void sense(const BudLightInput& in, BudLightOutput& out) = 0;
};

// The model `context.params.light_model` names; ValueError when it gives buds no light.
std::unique_ptr<BudLight> make_bud_light(const BudLightContext& context);

}  // namespace fspm::environment
