#include "environment/growth_params.hpp"

#include <toml++/toml.h>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/toml_text.hpp"

namespace fspm::environment {

std::string_view tropism_pairing_name(TropismPairing pairing) {
  return kTropismPairingNames.name(pairing);
}

TropismPairing tropism_pairing_from_name(std::string_view name) {
  return kTropismPairingNames.from_name(name);
}

GrowthParams growth_preset(std::string_view name, BudLightModel light_model,
                           TropismPairing pairing) {
  GrowthParams p;
  p.light_model = light_model;
  const bool text = pairing == TropismPairing::kText;
  int type = 0;
  if (name == "A" || name == "a") {
    p.phototropism = 0.25;
    p.gravitropism = 0.12;
  } else if (name == "B" || name == "b") {
    type = 1;
    p.phototropism = 0.45;
    p.gravitropism = text ? 0.44 : 0.03;
    p.apical_control = 0.48;
    p.pruning_factor = 0.09;
  } else if (name == "C" || name == "c") {
    type = 2;
    p.phototropism = text ? 0.03 : 0.44;
    p.gravitropism = 0.23;
    p.years = 30;
    p.pruning_factor = 0.06;
  } else {
    throw ValueError("unknown preset \"" + std::string(name) + "\", expected A, B or C");
  }
  // The vigour fitted for the model (its row of light_model_registry.hpp).
  p.alpha = bud_light_hook(light_model).preset_alpha[static_cast<std::size_t>(type)];
  return p;
}

namespace {

// The largest tip radius: pipe-model sums of its power stay finite for any tree that fits memory.
constexpr double kMaxTipRadiusM = 1.0;

template <typename Check>
void validate_light_model(const GrowthParams& p, const Check& check) {
  const ShadowGridParams& g = p.shadow_grid;
  auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  check(positive(g.voxel_size_m), "voxel_size_m", "a positive length");
  check(positive(g.shade_a), "shadow_a", "a positive number");
  check(g.shade_b > 1 && std::isfinite(g.shade_b), "shadow_b", "a number > 1");
  check(g.depth_voxels >= 0 && g.depth_voxels <= 64, "shadow_depth_voxels",
        "an integer in [0, 64]");
  check(positive(g.full_light), "full_light", "a positive number");
  check(g.obstacle_shade >= 0 && std::isfinite(g.obstacle_shade), "obstacle_shade",
        "a non-negative number");
  const SpaceColonizationParams& c = p.space_colonization;
  check(positive(c.marker_density_per_m3), "marker_density_per_m3", "a positive number");
  check(positive(c.perception_radius_m), "perception_radius_m", "a positive length");
  check(c.perception_angle_deg > 0 && c.perception_angle_deg <= 360, "perception_angle_deg",
        "an angle in (0, 360]");
  check(positive(c.occupancy_radius_m), "occupancy_radius_m", "a positive length");
  check(positive(c.region_radius_m), "marker_region_radius_m", "a positive length");
  check(positive(c.region_height_m), "marker_region_height_m", "a positive length");
}

// The preset a parameter table names, fitted for the table's light model and tropism pairing.
GrowthParams preset_from_table(const toml::table& table, const toml::node& preset,
                               const std::string& file_name) {
  auto line_of = [](const toml::node& n) { return static_cast<int>(n.source().begin.line); };
  const auto name = preset.value<std::string>();
  if (!name) throw ParseError("preset: expected \"A\", \"B\" or \"C\"", file_name, line_of(preset));
  // The name as a string, or "" (refused below) for another type.
  auto text_of = [](const toml::node& n) { return n.value<std::string>().value_or(""); };
  BudLightModel model = GrowthParams{}.light_model;
  TropismPairing pairing = kDefaultTropismPairing;
  const toml::node* at = nullptr;
  try {
    if ((at = table.get("light_model"))) model = bud_light_model_from_name(text_of(*at));
    if ((at = table.get("preset_tropisms"))) pairing = tropism_pairing_from_name(text_of(*at));
  } catch (const ValueError& e) {
    throw ValueError(e.message(), file_name, line_of(*at));
  }
  try {
    return growth_preset(*name, model, pairing);
  } catch (const ValueError& e) {
    throw ValueError(e.message(), file_name, line_of(preset));
  }
}

// "key=value" as a one-key TOML table; a value that is not TOML (a bare word) is a string.
toml::table override_table(const std::string& setting) {
  const auto eq = setting.find('=');
  const std::string key = setting.substr(0, eq);
  if (eq == std::string::npos || key.empty() ||
      key.find_first_not_of("abcdefghijklmnopqrstuvwxyz_0123456789") != std::string::npos) {
    throw ValueError("--set " + setting.substr(0, 60) + ": expected NAME=VALUE");
  }
  const std::string value = setting.substr(eq + 1);
  const std::string as_toml = key + " = " + value;
  try {
    return toml::parse(std::string_view(as_toml), std::string_view("--set"));
  } catch (const toml::parse_error&) {
    std::string quoted = "\"";
    for (const char c : value) {
      if (c == '"' || c == '\\') quoted += '\\';
      quoted += c;
    }
    const std::string as_string = key + " = " + quoted + "\"";
    try {
      return toml::parse(std::string_view(as_string), std::string_view("--set"));
    } catch (const toml::parse_error&) {
      throw ValueError("--set " + setting.substr(0, 60) + ": expected NAME=VALUE");
    }
  }
}

}  // namespace

void GrowthParams::validate() const {
  const GrowthParams& p = *this;
  auto check = [](bool ok, const char* name, const char* expected) {
    if (!ok) throw ValueError(std::string(name) + ": expected " + expected);
  };
  check(p.years >= 0 && p.years <= kMaxYears, "years", "an integer in [0, 1000]");
  static_assert(kMaxYears == 1000, "keep the message above in step");
  check(p.alpha > 0 && std::isfinite(p.alpha), "alpha", "a positive number");
  check(p.apical_control >= 0 && p.apical_control <= 1, "apical_control", "a number in [0, 1]");
  check(p.internode_length_m > 0 && std::isfinite(p.internode_length_m), "internode_length_m",
        "a positive length");
  check(p.max_shoot_metamers >= 1, "max_shoot_metamers", "an integer >= 1");
  check(p.max_internodes >= 1, "max_internodes", "an integer >= 1");
  check(p.max_height_m > 0 && !std::isnan(p.max_height_m), "max_height_m",
        "a positive length or inf");
  check(p.min_shoot_vigour >= 0 && std::isfinite(p.min_shoot_vigour), "min_shoot_vigour",
        "a non-negative number");
  check(p.light_half_saturation > 0 && !std::isnan(p.light_half_saturation),
        "light_half_saturation", "a positive number or inf");
  check(p.sky_light_fraction >= 0 && p.sky_light_fraction <= 1, "sky_light_fraction",
        "a fraction in [0, 1]");
  check(std::isfinite(p.branching_angle_deg), "branching_angle_deg", "a finite angle");
  check(std::isfinite(p.phyllotaxy_deg), "phyllotaxy_deg", "a finite angle");
  check(p.perturbation_deg >= 0 && p.perturbation_deg <= 90, "perturbation_deg",
        "an angle in [0, 90]");
  check(p.lateral_bud_lifetime_years >= 1, "lateral_bud_lifetime_years", "an integer >= 1");
  check(p.phototropism >= 0 && p.gravitropism >= 0 && p.phototropism + p.gravitropism < 1,
        "phototropism + gravitropism", "non-negative weights with a sum below 1 (Pirk eq. 4.7)");
  check(p.gravity_direction.allFinite() && p.gravity_direction.norm() > 0, "gravity_direction",
        "a non-zero vector");
  check(p.pruning_factor >= 0 && std::isfinite(p.pruning_factor), "pruning_factor",
        "a non-negative number");
  check(p.leaf_years >= 1, "leaf_years", "an integer >= 1");
  check(p.cluster_radius_m > 0 && std::isfinite(p.cluster_radius_m), "cluster_radius_m",
        "a positive length");
  check(p.gamma0 >= 0 && p.gamma0 <= 1, "gamma0", "a translucency in [0, 1]");
  check(p.light_directions >= 1, "light_directions", "an integer >= 1");
  check(p.light_significance >= 0 && p.light_significance < 1, "light_significance",
        "a number in [0, 1)");
  bud_light_hook(p.light_model);  // a model that lights buds, or a ValueError naming it
  validate_light_model(p, check);
  // A shoot tip is millimetres thick; above a metre its pipe-model powers overflow (1e300 made
  // every radius infinite, refused only by the tree writer, which named the output).
  check(p.tip_radius_m > 0 && p.tip_radius_m <= kMaxTipRadiusM, "tip_radius_m",
        "a positive length up to 1 m");
  check(p.pipe_exponent >= 1 && p.pipe_exponent <= 4, "pipe_exponent", "a number in [1, 4]");
}

namespace {

// How one key of a parameter file is read: a setter that stores a valid value (false for another
// type or a value out of range) and what the key expects, for the message.
using Setter = std::function<bool(const toml::node&)>;
using KeyTable = std::map<std::string, std::pair<Setter, std::string>>;
constexpr double kBig = 1e300;

Setter real(double& out, double lo, double hi) {
  return [&out, lo, hi](const toml::node& n) {
    const auto v = n.value<double>();
    if (!v || !std::isfinite(*v) || *v < lo || *v > hi) return false;
    out = *v;
    return true;
  };
}

template <typename Int>
Setter integer(Int& out, long long lo, long long hi) {
  return [&out, lo, hi](const toml::node& n) {
    if (!n.is_integer()) return false;
    const long long v = n.as_integer()->get();
    if (v < lo || v > hi) return false;
    out = static_cast<Int>(v);
    return true;
  };
}

Setter boolean(bool& out) {
  return [&out](const toml::node& n) {
    const auto v = n.value<bool>();
    if (!v || !n.is_boolean()) return false;
    out = *v;
    return true;
  };
}

// A positive number or inf ("no limit").
Setter positive_or_inf(double& out) {
  return [&out](const toml::node& n) {
    const auto v = n.value<double>();
    if (!v || std::isnan(*v) || !(*v > 0)) return false;
    out = *v;
    return true;
  };
}

// The keys of growth itself: cycles, vigour, shoots, tropisms, shedding, pipes.
KeyTable growth_keys(GrowthParams& p) {
  return {
      {"years", {integer(p.years, 0, 1000), "an integer in [0, 1000]"}},
      {"seed",
       {integer(p.seed, 0, std::numeric_limits<long long>::max()), "a non-negative integer"}},
      {"alpha", {real(p.alpha, 1e-12, kBig), "a positive number"}},
      {"apical_control", {real(p.apical_control, 0, 1), "a number in [0, 1]"}},
      {"internode_length_m", {real(p.internode_length_m, 1e-12, kBig), "a positive length"}},
      {"max_shoot_metamers", {integer(p.max_shoot_metamers, 1, 1000), "an integer in [1, 1000]"}},
      {"max_internodes",
       {integer(p.max_internodes, 1, std::numeric_limits<long long>::max()), "an integer >= 1"}},
      {"max_height_m", {positive_or_inf(p.max_height_m), "a positive length or inf"}},
      {"branching_angle_deg", {real(p.branching_angle_deg, -180, 180), "an angle in [-180, 180]"}},
      {"phyllotaxy_deg", {real(p.phyllotaxy_deg, -360, 360), "an angle in [-360, 360]"}},
      {"perturbation_deg", {real(p.perturbation_deg, 0, 90), "an angle in [0, 90]"}},
      {"lateral_bud_lifetime_years",
       {integer(p.lateral_bud_lifetime_years, 1, 1000), "an integer in [1, 1000]"}},
      {"phototropism", {real(p.phototropism, 0, 1), "a weight in [0, 1)"}},
      {"gravitropism", {real(p.gravitropism, 0, 1), "a weight in [0, 1)"}},
      {"pruning_factor", {real(p.pruning_factor, 0, kBig), "a non-negative number"}},
      {"leaf_years", {integer(p.leaf_years, 1, 1000), "an integer in [1, 1000]"}},
      {"cluster_radius_m", {real(p.cluster_radius_m, 1e-12, kBig), "a positive length"}},
      {"tip_radius_m",
       {real(p.tip_radius_m, 1e-12, kMaxTipRadiusM), "a positive length up to 1 m"}},
      {"pipe_exponent", {real(p.pipe_exponent, 1, 4), "a number in [1, 4]"}},
      {"keep_shed_pipes", {boolean(p.keep_shed_pipes), "true or false"}},
      {"min_shoot_vigour", {real(p.min_shoot_vigour, 0, kBig), "a non-negative number"}},
      {"gravity_direction",
       {[&p](const toml::node& n) {
          const auto* a = n.as_array();
          if (!a || a->size() != 3) return false;
          for (int k = 0; k < 3; ++k) {
            const auto v = (*a)[k].value<double>();
            if (!v || !std::isfinite(*v)) return false;
            p.gravity_direction[k] = *v;
          }
          return p.gravity_direction.norm() > 0;
        },
        "an array of 3 numbers, not all zero"}}};
}

// The keys of the light: the bud light model and its parameters, the light directions, the sky.
void add_light_keys(KeyTable& keys, GrowthParams& p, const std::string& file_name) {
  KeyTable light = {
      {"gamma0", {real(p.gamma0, 0, 1), "a translucency in [0, 1]"}},
      {"light_directions", {integer(p.light_directions, 1, 1 << 20), "an integer >= 1"}},
      {"light_significance", {real(p.light_significance, 0, 0.999), "a number in [0, 1)"}},
      {"sky_light_fraction", {real(p.sky_light_fraction, 0, 1), "a fraction in [0, 1]"}},
      {"light_half_saturation",
       {positive_or_inf(p.light_half_saturation), "a positive number or inf"}},
      {"light_model",
       {[&p](const toml::node& n) {
          const std::string name = n.value<std::string>().value_or("");
          // A model of adaptation only (canopy) is refused by the registry, which names its use.
          if (kLightModelNames.find(name)) p.light_model = bud_light_model_from_name(name);
          return kBudLightModelNames.find(name).has_value();
        },
        kBudLightModelNames.expected()}},
      {"voxel_size_m", {real(p.shadow_grid.voxel_size_m, 1e-3, kBig), "a length >= 0.001"}},
      {"shadow_a", {real(p.shadow_grid.shade_a, 1e-12, kBig), "a positive number"}},
      {"shadow_b", {real(p.shadow_grid.shade_b, 1.000001, kBig), "a number > 1"}},
      {"shadow_depth_voxels",
       {integer(p.shadow_grid.depth_voxels, 0, 64), "an integer in [0, 64]"}},
      {"full_light", {real(p.shadow_grid.full_light, 1e-12, kBig), "a positive number"}},
      {"obstacle_shade", {real(p.shadow_grid.obstacle_shade, 0, kBig), "a non-negative number"}},
      {"marker_density_per_m3",
       {real(p.space_colonization.marker_density_per_m3, 1e-12, kBig), "a positive number"}},
      {"perception_radius_m",
       {real(p.space_colonization.perception_radius_m, 1e-6, kBig), "a positive length"}},
      {"perception_angle_deg",
       {real(p.space_colonization.perception_angle_deg, 1e-6, 360), "an angle in (0, 360]"}},
      {"occupancy_radius_m",
       {real(p.space_colonization.occupancy_radius_m, 1e-6, kBig), "a positive length"}},
      {"marker_region_radius_m",
       {real(p.space_colonization.region_radius_m, 1e-6, kBig), "a positive length"}},
      {"marker_region_height_m",
       {real(p.space_colonization.region_height_m, 1e-6, kBig), "a positive length"}},
      {"sky",
       {[&p, &file_name](const toml::node& n) {
          p.site_sky = parse_site_sky(n, file_name);
          return true;
        },
        "a table { site = { latitude, longitude, elevation }, date, hours | days }"}}};
  keys.merge(light);
}

// The file's table with the command line's NAME=VALUE settings over it; `from_command_line` gets
// their keys.
toml::table table_with_overrides(std::string_view text, const std::string& file_name,
                                 const std::vector<std::string>& overrides,
                                 std::set<std::string>& from_command_line) {
  toml::table table = parse_toml_text(text, file_name);
  for (const std::string& setting : overrides) {
    for (auto&& [key, node] : override_table(setting)) {
      from_command_line.insert(std::string(key.str()));
      table.insert_or_assign(key, std::move(node));
    }
  }
  return table;
}

// The parameters a table starts from: its preset's, or the defaults.
GrowthParams base_params(const toml::table& table, const std::string& file_name) {
  if (auto preset = table["preset"]) return preset_from_table(table, *preset.node(), file_name);
  if (const toml::node* n = table.get("preset_tropisms")) {
    throw ValueError("preset_tropisms: chooses the tropisms of a preset; expected a preset key too",
                     file_name, static_cast<int>(n->source().begin.line));
  }
  return GrowthParams{};
}

// Every key of `table` through its setter; an unknown key or a refused value is a ValueError at
// its line, or naming --set when the command line gave it.
void apply_keys(const toml::table& table, const KeyTable& keys,
                const std::set<std::string>& from_command_line, const std::string& file_name) {
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    const int line = static_cast<int>(node.source().begin.line);
    const int column = static_cast<int>(node.source().begin.column);
    if (name == "preset" || name == "preset_tropisms") continue;
    const auto it = keys.find(name);
    const bool set = from_command_line.count(name) > 0;
    if (it == keys.end()) {
      std::vector<std::string> known{"preset", "preset_tropisms"};
      for (const auto& [k, setter] : keys) known.push_back(k);
      const std::string what = unknown_key_message(name.substr(0, 60), name, known) +
                               " (the keys are listed in docs/environment.md)";
      if (set) throw ValueError("--set " + what);
      throw ValueError(what, file_name, line, column);
    }
    bool ok = false;
    try {
      ok = it->second.first(node);
    } catch (const ValueError& e) {  // a setter's own refusal, placed at the key
      if (set) throw ValueError("--set " + name + ": " + e.message());
      throw ValueError(e.message(), file_name, line, column);
    }
    if (!ok) {
      if (set) throw ValueError("--set " + name + ": expected " + it->second.second);
      throw ValueError(name + ": expected " + it->second.second, file_name, line, column);
    }
  }
}

}  // namespace

GrowthParams parse_growth_params(std::string_view text, const std::string& file_name,
                                 const std::vector<std::string>& overrides) {
  std::set<std::string> from_command_line;
  const toml::table table = table_with_overrides(text, file_name, overrides, from_command_line);
  GrowthParams p = base_params(table, file_name);
  // The setters write into p, which stays in place while they are used.
  KeyTable keys = growth_keys(p);
  add_light_keys(keys, p, file_name);
  apply_keys(table, keys, from_command_line, file_name);
  try {
    p.validate();
  } catch (const ValueError& e) {
    throw ValueError(e.message(), file_name);
  }
  return p;
}

GrowthParams read_growth_params(const std::string& path,
                                const std::vector<std::string>& overrides) {
  const std::string text = read_text_input_file(path);
  // Every key has a default, so a file without any (empty, or only comments) would grow the
  // default tree: almost always a truncated or wrong file rather than a choice.
  if (parse_toml_text(text, path).empty()) {
    throw ParseError("no parameter in the file; expected growth parameters such as preset = \"A\"",
                     path, 1);
  }
  return parse_growth_params(text, path, overrides);
}

}  // namespace fspm::environment
