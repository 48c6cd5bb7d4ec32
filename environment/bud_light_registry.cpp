// The one place a bud light model is registered: its BudLightModel (named and described in
// kBudLightModelNames, environment/growth_params.hpp) and the factory of its file.
#include <array>
#include <utility>

#include "environment/bud_light.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {

std::unique_ptr<BudLight> make_sky_bud_light(const BudLightContext& context);
std::unique_ptr<BudLight> make_shadow_grid_bud_light(const BudLightContext& context);
std::unique_ptr<BudLight> make_space_colonization_bud_light(const BudLightContext& context);

namespace {

using BudLightFactory = std::unique_ptr<BudLight> (*)(const BudLightContext&);

constexpr std::array<std::pair<BudLightModel, BudLightFactory>, 3> kBudLights{{
    {BudLightModel::kSky, make_sky_bud_light},
    {BudLightModel::kShadowGrid, make_shadow_grid_bud_light},
    {BudLightModel::kSpaceColonization, make_space_colonization_bud_light},
}};
static_assert(kBudLights.size() == kBudLightModelNames.size(),
              "every named bud light model has its factory");

}  // namespace

std::unique_ptr<BudLight> make_bud_light(const BudLightContext& context) {
  for (const auto& [model, make] : kBudLights) {
    if (model == context.params.light_model) return make(context);
  }
  throw ValueError("growth: no bud light model '" +
                   std::string(bud_light_model_name(context.params.light_model)) + "'");
}

}  // namespace fspm::environment
