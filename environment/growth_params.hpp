#pragma once
// Parameters of the self-organizing growth model (Palubicki et al. 2009 as used by Pirk 4.5.4),
// read from TOML (docs/environment.md) or taken from Pirk's tree types A, B and C.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "environment/light_model_registry.hpp"
#include "environment/shadow_grid.hpp"
#include "environment/site_sky.hpp"
#include "environment/space_colonization.hpp"
#include "fspm/name_table.hpp"

namespace fspm::environment {

inline constexpr int kMaxYears = 1000;  // growth cycles a simulation may run

struct GrowthParams {
  int years = 20;          // growth cycles, at most kMaxYears
  std::uint64_t seed = 1;  // randomness only for small heading perturbations
  // Borchert-Honda allocation (Palubicki eq. for v_base = alpha * Q_base, apical control lambda).
  double alpha = 3.0;
  double apical_control = 0.47;
  // Shoots (Palubicki's continuous option): a bud with vigour v >= min_shoot_vigour grows a shoot
  // of total length v * internode_length_m, in n = round(v) metamers (at least 1, at most
  // max_shoot_metamers) of equal length, so no fraction of v is lost.
  double internode_length_m = 0.15;
  int max_shoot_metamers = 5;
  double min_shoot_vigour = 0.5;
  // Guards against parameters that make the tree explode (GrowthLimitError): growth stops when
  // the tree has more internodes than this, or is taller than max_height_m (the tallest trees
  // measured are about 116 m; a taller tree here means the vigour runs away).
  std::size_t max_internodes = 1'000'000;
  double max_height_m = 150.0;
  double branching_angle_deg = 40.0;
  double phyllotaxy_deg = 137.5;
  double perturbation_deg = 4.0;
  int lateral_bud_lifetime_years = 4;  // dormant lateral buds die after this many cycles
  // Tropisms, Pirk eq. 4.6-4.7: h = w_s d_o + (1 - w_s) t, t the weighted mean of the
  // phototropism (towards the bud's mean light direction) and gravitropism directions.
  double phototropism = 0.25;
  double gravitropism = 0.12;
  // Direction gravitropism bends towards (Palubicki: down, so a positive weight makes branches
  // droop); use (0, 0, 1) for negative gravitropism.
  Eigen::Vector3d gravity_direction = -Eigen::Vector3d::UnitZ();
  // Shedding: a lateral branch with light per supported internode below this is removed.
  double pruning_factor = 0.1;
  // Leaf clusters: one sphere per shoot younger than leaf_years; radius
  // max(cluster_radius_m, half the shoot length); translucency gamma0^r (Pirk eq. 4.4).
  int leaf_years = 2;
  double cluster_radius_m = 0.3;
  double gamma0 = 0.5;
  // Where a bud's light Q and optimal growth direction V come from (Palubicki et al. 2009, 4.1): a
  // model of kBudLightModelNames (light_model_registry.hpp).
  BudLightModel light_model = BudLightModel::kShadowGrid;
  // Share of the open sky's light that reaches the stand (1: open site); scales every bud's Q.
  double sky_light_fraction = 1.0;
  // A real sky (`sky = { site = {...}, date, hours | days }`): its light per direction
  // (sky_distribution.hpp) replaces the cos^2 sky of the `sky` bud light and the leaves' light,
  // which also get their PAR; the shadow grid's pyramid stays vertical.
  std::optional<SiteSky> site_sky;
  // Photosynthetic light response, a rectangular hyperbola (Thornley and Johnson 1990): the
  // resource of a bud with light Q is P(Q) = Q (1 + K) / (Q + K), 1 in full light, with K the
  // half-saturation light; K = inf gives Palubicki's linear Q. It is what keeps a little less
  // light from costing much more than a little size (docs/environment.md, "Size against light").
  double light_half_saturation = 0.2;
  // kSky: fewer directions and a coarser shadow-volume cutoff than `fspm light`.
  int light_directions = 64;
  double light_significance = 0.01;
  ShadowGridParams shadow_grid;                // kShadowGrid
  SpaceColonizationParams space_colonization;  // kSpaceColonization
  // Geometry: pipe model r^n = sum r_child^n from the tip radius.
  double tip_radius_m = 0.004;
  double pipe_exponent = 2.5;
  // Radii keep the pipes of shed branches (Shinozaki et al. 1964: the pipes of lost branches stay
  // in the wood below them as disused pipes), each shed branch counting with the pipes it had
  // when it was shed. Off: radii from the living branches alone.
  bool keep_shed_pipes = false;
  // Throws ValueError naming the parameter when one is out of range.
  void validate() const;
};

// Which tropism weights Pirk's tree types take. Pirk's text (4.5.4) pairs them as A 0.25 / 0.12,
// B 0.45 / 0.44, C 0.03 / 0.23 (phototropism / gravitropism); the captions of the thesis'
// appendix tables read A 0.25 / 0.12, B 0.45 / 0.03, C 0.44 / 0.23.
enum class TropismPairing { kText, kAppendix };
inline constexpr NameTable<TropismPairing, 2> kTropismPairingNames{
    "preset_tropisms",
    {{TropismPairing::kText, "text", "the pairing of Pirk's text, 4.5.4"},
     {TropismPairing::kAppendix, "appendix", "the pairing of the appendix tables' captions"}}};
// The pairing of a preset that names none (preset_tropisms, fspm grow --tropisms).
inline constexpr TropismPairing kDefaultTropismPairing = TropismPairing::kText;
std::string_view tropism_pairing_name(TropismPairing pairing);  // "text", "appendix"
// Throws ValueError for a name other than "text" and "appendix".
TropismPairing tropism_pairing_from_name(std::string_view name);

// Pirk's tree types (4.5.4) "A", "B", "C" (C older and with a smaller pruning factor), with the
// vigour alpha fitted for `light_model` so that trees of 10 / 20 / 30 cycles have about Pirk
// Table 4.2's sizes. Throws ValueError for another name.
GrowthParams growth_preset(std::string_view name,
                           BudLightModel light_model = BudLightModel::kShadowGrid,
                           TropismPairing pairing = kDefaultTropismPairing);

// Reads a TOML parameter file; `preset = "A"` starts from a preset (fitted for the file's
// `light_model` and `preset_tropisms`), other keys override it.
// Throws ParseError (bad TOML, unknown key) or ValueError (value out of range) naming file and
// line.
GrowthParams read_growth_params(const std::string& path,
                                const std::vector<std::string>& overrides = {});
// `overrides` are "key=value" settings applied over the text's keys (the value in TOML syntax; a
// bare word is taken as a string), as `fspm grow --set` gives them.
GrowthParams parse_growth_params(std::string_view text, const std::string& file_name = "<params>",
                                 const std::vector<std::string>& overrides = {});

}  // namespace fspm::environment
