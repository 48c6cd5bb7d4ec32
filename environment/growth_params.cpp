#include "environment/growth_params.hpp"

#include <toml++/toml.h>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "fspm/error.hpp"

namespace fspm::environment {

GrowthParams growth_preset(std::string_view name) {
  // The defaults are type A. Vigour (alpha, apical control, and for B the pruning factor) is
  // fitted per type so that trees of 10 / 20 / 30 cycles have about Pirk Table 4.2's 530 /
  // 2 500 / 9 100 internodes, averaged over seeds 1-12 (docs/environment.md, "Presets").
  GrowthParams p;
  if (name == "A" || name == "a") {
    p.phototropism = 0.25;
    p.gravitropism = 0.12;
  } else if (name == "B" || name == "b") {
    p.phototropism = 0.45;
    p.gravitropism = 0.44;
    p.alpha = 2.9;
    p.apical_control = 0.48;
    p.pruning_factor = 0.09;
  } else if (name == "C" || name == "c") {
    p.phototropism = 0.03;
    p.gravitropism = 0.23;
    p.years = 30;
    p.pruning_factor = 0.06;
    p.alpha = 3.2;  // fitted to the 10- and 20-cycle sizes (it stays smaller at 30, see docs)
  } else {
    throw ValueError("unknown preset \"" + std::string(name) + "\", expected A, B or C");
  }
  return p;
}

void validate(const GrowthParams& p) {
  auto check = [](bool ok, const char* name, const char* expected) {
    if (!ok) throw ValueError(std::string(name) + ": expected " + expected);
  };
  check(p.years >= 0 && p.years <= 1000, "years", "an integer in [0, 1000]");
  check(p.alpha > 0 && std::isfinite(p.alpha), "alpha", "a positive number");
  check(p.apical_control >= 0 && p.apical_control <= 1, "apical_control", "a number in [0, 1]");
  check(p.internode_length_m > 0 && std::isfinite(p.internode_length_m), "internode_length_m",
        "a positive length");
  check(p.max_shoot_metamers >= 1, "max_shoot_metamers", "an integer >= 1");
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
  check(p.tip_radius_m > 0 && std::isfinite(p.tip_radius_m), "tip_radius_m", "a positive length");
  check(p.pipe_exponent >= 1 && p.pipe_exponent <= 4, "pipe_exponent", "a number in [1, 4]");
}

GrowthParams parse_growth_params(std::string_view text, const std::string& file_name) {
  toml::table table;
  try {
    table = toml::parse(text, file_name);
  } catch (const toml::parse_error& e) {
    throw ParseError("expected valid TOML (" + std::string(e.description()) + ")", file_name,
                     static_cast<int>(e.source().begin.line),
                     static_cast<int>(e.source().begin.column));
  }
  GrowthParams p;
  if (auto preset = table["preset"]) {
    const auto name = preset.value<std::string>();
    const int line = static_cast<int>(preset.node()->source().begin.line);
    if (!name) throw ParseError("preset: expected \"A\", \"B\" or \"C\"", file_name, line);
    try {
      p = growth_preset(*name);
    } catch (const ValueError& e) {
      throw ValueError(e.message(), file_name, line);
    }
  }
  using Setter = std::function<bool(const toml::node&)>;
  auto real = [](double& out, double lo, double hi) -> Setter {
    return [&out, lo, hi](const toml::node& n) {
      const auto v = n.value<double>();
      if (!v || !std::isfinite(*v) || *v < lo || *v > hi) return false;
      out = *v;
      return true;
    };
  };
  auto integer = [](auto& out, long long lo, long long hi) -> Setter {
    return [&out, lo, hi](const toml::node& n) {
      if (!n.is_integer()) return false;
      const long long v = n.as_integer()->get();
      if (v < lo || v > hi) return false;
      out = static_cast<std::remove_reference_t<decltype(out)>>(v);
      return true;
    };
  };
  constexpr double kBig = 1e300;
  const std::map<std::string, std::pair<Setter, std::string>> keys = {
      {"years", {integer(p.years, 0, 1000), "an integer in [0, 1000]"}},
      {"seed",
       {integer(p.seed, 0, std::numeric_limits<long long>::max()), "a non-negative integer"}},
      {"alpha", {real(p.alpha, 1e-12, kBig), "a positive number"}},
      {"apical_control", {real(p.apical_control, 0, 1), "a number in [0, 1]"}},
      {"internode_length_m", {real(p.internode_length_m, 1e-12, kBig), "a positive length"}},
      {"max_shoot_metamers", {integer(p.max_shoot_metamers, 1, 1000), "an integer in [1, 1000]"}},
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
      {"gamma0", {real(p.gamma0, 0, 1), "a translucency in [0, 1]"}},
      {"light_directions", {integer(p.light_directions, 1, 1 << 20), "an integer >= 1"}},
      {"light_significance", {real(p.light_significance, 0, 0.999), "a number in [0, 1)"}},
      {"tip_radius_m", {real(p.tip_radius_m, 1e-12, kBig), "a positive length"}},
      {"pipe_exponent", {real(p.pipe_exponent, 1, 4), "a number in [1, 4]"}},
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
        "an array of 3 numbers, not all zero"}},
  };
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    const int line = static_cast<int>(node.source().begin.line);
    const int column = static_cast<int>(node.source().begin.column);
    if (name == "preset") continue;
    const auto it = keys.find(name);
    if (it == keys.end()) {
      throw ParseError("unknown parameter \"" + name +
                           "\"; expected one of the keys in "
                           "docs/environment.md",
                       file_name, line, column);
    }
    if (!it->second.first(node)) {
      throw ValueError(name + ": expected " + it->second.second, file_name, line, column);
    }
  }
  try {
    validate(p);
  } catch (const ValueError& e) {
    throw ValueError(e.message(), file_name);
  }
  return p;
}

GrowthParams read_growth_params(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open parameter file for reading", path);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_growth_params(text.str(), path);
}

}  // namespace fspm::environment
