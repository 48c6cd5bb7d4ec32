#pragma once
// The one list of fspm's light models, shared by growth and plastic adaptation: each model is one
// row of kLightModels with its name, what it means and the hooks of the uses it supports, the
// light of every bud for growth (a BudLight, bud_light.hpp; Palubicki et al. 2009, step 1) and
// the light of every leaf cluster for the analysis and plastic adaptation of a grown tree (a
// PlasticLight, plastic_light.hpp; Pirk 4.3-4.4). A model is one file defining the factory of
// each hook it has (`sky_bud_light.cpp`, `canopy_plastic_light.cpp`, ...) and its row here; the
// name tables of both uses, the parameter files, `fspm grow --light-model`, `fspm adapt
// --light-model`, the experiments and Python all read these rows.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "fspm/name_table.hpp"

namespace fspm::environment {

class BudLight;
struct BudLightContext;
class PlasticLight;
struct AnalysisParams;

// The light models, one value per row of kLightModels.
enum class LightModelKind {
  kCanopy,             // the leaves as turbid media through a leaf light model (canopy_light.hpp)
  kSky,                // the sky hemisphere of Pirk eq. 4.3, shaded by leaf clusters and occluders
  kShadowGrid,         // Palubicki's shadow propagation in a voxel grid (local shade)
  kSpaceColonization,  // marker points and perception cones (Runions et al. 2007)
};
// Growth speaks of the model of its buds, adaptation of the model of its leaf clusters: the same
// values, each use taking the models that have its hook.
using BudLightModel = LightModelKind;
using ClusterLightModel = LightModelKind;

using BudLightFactory = std::unique_ptr<BudLight> (*)(const BudLightContext&);
using PlasticLightFactory = std::unique_ptr<PlasticLight> (*)(const AnalysisParams&);

// Growth: the factory of the model's BudLight, and the vigour alpha of Pirk's tree types A, B and
// C fitted for it so that 20-cycle trees (seeds 1-8) have about Pirk Table 4.2's 2 541 internodes
// (growth_preset; docs/environment.md, "Presets").
struct BudLightHook {
  BudLightFactory make = nullptr;
  std::array<double, 3> preset_alpha{};
};

struct LightModelEntry {
  LightModelKind kind{};
  std::string_view name;  // in parameter files and options
  std::string_view help;  // what it means, for --help and docstrings
  BudLightHook bud;       // make == nullptr: the model gives buds no light
  // The model's PlasticLight; nullptr: it gives leaf clusters no light.
  PlasticLightFactory plastic = nullptr;
};

// The factories, each defined in its model's file.
std::unique_ptr<BudLight> make_sky_bud_light(const BudLightContext& context);
std::unique_ptr<BudLight> make_shadow_grid_bud_light(const BudLightContext& context);
std::unique_ptr<BudLight> make_space_colonization_bud_light(const BudLightContext& context);
std::unique_ptr<PlasticLight> make_canopy_plastic_light(const AnalysisParams& params);
std::unique_ptr<PlasticLight> make_sky_plastic_light(const AnalysisParams& params);
std::unique_ptr<PlasticLight> make_shadow_grid_plastic_light(const AnalysisParams& params);

// The registry. The order is that of the help texts and of "expected ..." in messages.
inline constexpr auto kLightModels = std::to_array<LightModelEntry>({
    {LightModelKind::kCanopy,
     "canopy",
     "the leaves as turbid media, through the canopy model",
     {},
     make_canopy_plastic_light},
    {LightModelKind::kSky,
     "sky",
     "the sky hemisphere shaded by the leaf clusters as caps, Pirk eq. 4.3",
     {make_sky_bud_light, {1.42, 1.66, 1.22}},
     make_sky_plastic_light},
    {LightModelKind::kShadowGrid,
     "shadow_grid",
     "Palubicki's voxel shade",
     {make_shadow_grid_bud_light, {1.94, 2.20, 1.77}},
     make_shadow_grid_plastic_light},
    {LightModelKind::kSpaceColonization,
     "space_colonization",
     "marker points and perception cones, Runions et al. 2007",
     {make_space_colonization_bud_light, {1.15, 1.80, 1.41}},
     nullptr},
});

constexpr bool lights_buds(const LightModelEntry& e) { return e.bud.make != nullptr; }
constexpr bool lights_clusters(const LightModelEntry& e) { return e.plastic != nullptr; }

namespace light_model_detail {

template <bool (*Uses)(const LightModelEntry&)>
constexpr std::size_t count() {
  std::size_t n = 0;
  for (const LightModelEntry& e : kLightModels) n += Uses(e) ? 1 : 0;
  return n;
}

// The name table of the rows that have a use.
template <bool (*Uses)(const LightModelEntry&), std::size_t N = count<Uses>()>
constexpr NameTable<LightModelKind, N> names() {
  NamedValue<LightModelKind> rows[N]{};
  std::size_t k = 0;
  for (const LightModelEntry& e : kLightModels) {
    if (Uses(e)) rows[k++] = {e.kind, e.name, e.help};
  }
  return NameTable<LightModelKind, N>("light_model", rows);
}

constexpr bool any(const LightModelEntry&) { return true; }

// Each kind and each name in one row only.
constexpr bool rows_are_distinct() {
  for (std::size_t i = 0; i < kLightModels.size(); ++i) {
    for (std::size_t j = i + 1; j < kLightModels.size(); ++j) {
      if (kLightModels[i].kind == kLightModels[j].kind) return false;
      if (kLightModels[i].name == kLightModels[j].name) return false;
    }
  }
  return true;
}
static_assert(rows_are_distinct(), "a light model registered twice");

}  // namespace light_model_detail

// Every model, and those of each use (the names of `fspm grow` and of `fspm adapt`).
inline constexpr auto kLightModelNames = light_model_detail::names<light_model_detail::any>();
inline constexpr auto kBudLightModelNames = light_model_detail::names<lights_buds>();
inline constexpr auto kClusterLightModelNames = light_model_detail::names<lights_clusters>();
static_assert(kLightModelNames.size() == kLightModels.size());

// The row of a model.
const LightModelEntry& light_model_entry(LightModelKind kind);
std::string_view light_model_name(LightModelKind kind);

// The name used in parameter files ("sky", "shadow_grid", "space_colonization").
std::string_view bud_light_model_name(BudLightModel model);
// The model of a name; throws ValueError naming the models of growth for an unknown name, or
// saying that a model without a bud light (canopy) has none.
BudLightModel bud_light_model_from_name(std::string_view name);
// "canopy", "sky" or "shadow_grid"; throws ValueError naming the models of adaptation otherwise,
// or saying that a model without a cluster light (space_colonization) has none.
ClusterLightModel cluster_light_model_from_name(const std::string& name);
std::string_view cluster_light_model_name(ClusterLightModel model);

// The hooks of a use; throw ValueError naming the model and the models that have the hook when it
// has none (`context` goes before the message).
const BudLightHook& bud_light_hook(LightModelKind kind);
PlasticLightFactory plastic_light_factory(LightModelKind kind, std::string_view context = {});

}  // namespace fspm::environment
