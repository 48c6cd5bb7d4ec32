// The lookups of the light-model registry (light_model_registry.hpp): the names both ways, and
// each use's hook with the message that names a model asked for a use it does not have.
#include "environment/light_model_registry.hpp"

#include "environment/bud_light.hpp"
#include "environment/plastic_light.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

// "light_model 'canopy' gives no light to buds: expected sky, shadow_grid or space_colonization".
template <std::size_t N>
[[noreturn]] void throw_no_hook(std::string_view context, LightModelKind kind,
                                std::string_view what, const NameTable<LightModelKind, N>& use) {
  std::string message = "light_model '" + std::string(light_model_name(kind)) +
                        "' gives no light to " + std::string(what) + ": expected " + use.expected();
  if (!context.empty()) message = std::string(context) + ": " + message;
  throw ValueError(message);
}

// The model of a name in the table of one use: a model of another use is refused by name, any
// other name with the closest name of the use.
template <std::size_t N>
LightModelKind from_name_for_use(std::string_view name, std::string_view context,
                                 std::string_view what, const NameTable<LightModelKind, N>& use) {
  if (const auto kind = use.find(name)) return *kind;
  if (const auto other = kLightModelNames.find(name)) throw_no_hook(context, *other, what, use);
  return use.from_name(name, context);
}

constexpr std::string_view kBuds = "buds (growth)";
constexpr std::string_view kClusters = "leaf clusters (plastic adaptation)";

}  // namespace

const LightModelEntry& light_model_entry(LightModelKind kind) {
  for (const LightModelEntry& e : kLightModels) {
    if (e.kind == kind) return e;
  }
  throw ValueError("no light model number " + std::to_string(static_cast<int>(kind)));
}

std::string_view light_model_name(LightModelKind kind) { return kLightModelNames.name(kind); }

std::string_view bud_light_model_name(BudLightModel model) { return light_model_name(model); }

BudLightModel bud_light_model_from_name(std::string_view name) {
  return from_name_for_use(name, {}, kBuds, kBudLightModelNames);
}

ClusterLightModel cluster_light_model_from_name(const std::string& name) {
  return from_name_for_use(name, "plastic analysis", kClusters, kClusterLightModelNames);
}

std::string_view cluster_light_model_name(ClusterLightModel model) {
  return light_model_name(model);
}

const BudLightHook& bud_light_hook(LightModelKind kind) {
  const LightModelEntry& e = light_model_entry(kind);
  if (!lights_buds(e)) throw_no_hook({}, kind, kBuds, kBudLightModelNames);
  return e.bud;
}

PlasticLightFactory plastic_light_factory(LightModelKind kind, std::string_view context) {
  const LightModelEntry& e = light_model_entry(kind);
  if (!lights_clusters(e)) throw_no_hook(context, kind, kClusters, kClusterLightModelNames);
  return e.plastic;
}

std::unique_ptr<BudLight> make_bud_light(const BudLightContext& context) {
  const LightModelEntry& e = light_model_entry(context.params.light_model);
  if (!lights_buds(e)) throw_no_hook("growth", e.kind, kBuds, kBudLightModelNames);
  return e.bud.make(context);
}

std::unique_ptr<PlasticLight> make_plastic_light(const AnalysisParams& params,
                                                 std::string_view context) {
  return plastic_light_factory(params.light_model, context)(params);
}

}  // namespace fspm::environment
