#include "greenlab/plant_params.hpp"

#include <toml++/toml.h>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <string_view>

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/toml_text.hpp"

namespace fspm::greenlab {
namespace {

int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }
int column_of(const toml::node& node) { return static_cast<int>(node.source().begin.column); }

// Reads the keys of one TOML table, remembering which were used so unknown keys can be reported.
class TableReader {
 public:
  TableReader(const toml::table& table, std::string path, std::string file)
      : table_(table), path_(std::move(path)), file_(std::move(file)) {}

  std::string key_name(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  }

  const toml::node* find(std::string_view key) {
    used_.insert(std::string(key));
    return table_.get(key);
  }

  const toml::node& require(std::string_view key) {
    const toml::node* node = find(key);
    if (node == nullptr) {
      throw ParseError("missing key '" + key_name(key) + "'", file_, line_of(table_),
                       column_of(table_));
    }
    return *node;
  }

  std::int64_t integer(std::string_view key, const toml::node& node) const {
    if (auto v = node.value_exact<std::int64_t>()) return *v;
    throw ParseError("key '" + key_name(key) + "' must be an integer", file_, line_of(node),
                     column_of(node));
  }

  double number(std::string_view key, const toml::node& node) const {
    if (auto v = node.value<double>(); v && (node.is_floating_point() || node.is_integer())) {
      return *v;
    }
    throw ParseError("key '" + key_name(key) + "' must be a number", file_, line_of(node),
                     column_of(node));
  }

  int get_int(std::string_view key, int fallback, std::int64_t min_value, bool required = false) {
    const toml::node* node = required ? &require(key) : find(key);
    if (node == nullptr) return fallback;
    const std::int64_t v = integer(key, *node);
    if (v < min_value || v > 1'000'000'000) {
      throw ParseError("key '" + key_name(key) + "' is " + std::to_string(v) + ", expected " +
                           (min_value == 0 ? "a count >= 0" : ">= " + std::to_string(min_value)),
                       file_, line_of(*node), column_of(*node));
    }
    return static_cast<int>(v);
  }

  // An expansion time in cycles: at most the longest simulation, since the beta law of
  // functional.cpp is tabulated over the whole expansion (10^8 cycles would take 800 MB).
  int get_expansion(std::string_view key) {
    const int v = get_int(key, 1, 1);
    if (v > kMaxCycles) {
      const toml::node& node = *table_.get(key);
      throw ParseError("key '" + key_name(key) + "' is " + std::to_string(v) +
                           " cycles, expected at most " + std::to_string(kMaxCycles) +
                           " (plant.cycles is at most that)",
                       file_, line_of(node), column_of(node));
    }
    return v;
  }

  double get_double(std::string_view key, double fallback, double lo, double hi,
                    const char* expected) {
    const toml::node* node = find(key);
    if (node == nullptr) return fallback;
    const double v = number(key, *node);
    if (!(v >= lo && v <= hi)) {
      std::ostringstream msg;
      msg << "key '" << key_name(key) << "' is " << v << ", expected " << expected;
      throw ParseError(msg.str(), file_, line_of(*node), column_of(*node));
    }
    return v;
  }

  double get_probability(std::string_view key) {
    return get_double(key, 1.0, 0.0, 1.0, "a probability in [0, 1]");
  }
  double get_nonnegative(std::string_view key, double fallback) {
    return get_double(key, fallback, 0.0, std::numeric_limits<double>::max(), "a value >= 0");
  }
  double get_positive(std::string_view key, double fallback) {
    const double v = get_nonnegative(key, fallback);
    if (v <= 0.0) {
      throw ParseError("key '" + key_name(key) + "' must be > 0", file_, line_of(*table_.get(key)),
                       column_of(*table_.get(key)));
    }
    return v;
  }
  double get_any(std::string_view key, double fallback) {
    return get_double(key, fallback, -std::numeric_limits<double>::max(),
                      std::numeric_limits<double>::max(), "a finite number");
  }

  // Every key the reader asked for is a known one.
  void reject_unknown() const {
    for (const auto& [k, node] : table_) {
      if (!used_.contains(std::string(k.str()))) {
        const std::vector<std::string> known(used_.begin(), used_.end());
        throw ValueError(unknown_key_message(key_name(k.str()), k.str(), known), file_,
                         line_of(node), column_of(node));
      }
    }
  }

  const std::string& file() const { return file_; }

 private:
  const toml::table& table_;
  std::string path_;
  std::string file_;
  std::set<std::string, std::less<>> used_;
};

const toml::table& as_table(const toml::node& node, const std::string& key,
                            const std::string& file) {
  if (const auto* t = node.as_table()) return *t;
  throw ParseError("key '" + key + "' must be a table", file, line_of(node), column_of(node));
}

const toml::array& as_array(const toml::node& node, const std::string& key,
                            const std::string& file) {
  if (const auto* a = node.as_array()) return *a;
  throw ParseError("key '" + key + "' must be an array", file, line_of(node), column_of(node));
}

MetamerRun read_run(const toml::table& table, const std::string& path, const std::string& file) {
  TableReader r(table, path, file);
  MetamerRun run;
  run.count = r.get_int("count", 0, 0, true);
  if (const toml::node* ax = r.find("axillary")) {
    const auto& arr = as_array(*ax, r.key_name("axillary"), file);
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const std::string p = path + ".axillary[" + std::to_string(i) + "]";
      TableReader b(as_table(arr[i], p, file), p, file);
      AxillaryBuds buds;
      buds.age = b.get_int("age", 0, 1, true);
      buds.count = b.get_int("count", 1, 0);
      b.reject_unknown();
      run.axillary.push_back(buds);
    }
  }
  r.reject_unknown();
  return run;
}

// Source positions of each age's keys, kept to point cross-field errors at the right line.
struct AgeLines {
  int table = 0;
  int next_age = 0;
  std::vector<std::vector<int>> axillary;  // per run, per axillary entry
};

AgeParams read_age(const toml::table& table, const std::string& path, const std::string& file,
                   AgeLines& lines) {
  TableReader r(table, path, file);
  AgeParams a;
  lines.table = line_of(table);
  a.index = r.get_int("index", 0, 1, true);
  a.duration = r.get_int("duration", 1, 1, true);
  a.next_age = r.get_int("next_age", 0, 0, true);
  lines.next_age = line_of(*r.find("next_age"));
  if (const toml::node* t = r.find("terminal")) {
    const auto s = t->value<std::string>();
    if (s == "flower") {
      a.terminal = Terminal::kFlower;
    } else if (s == "none") {
      a.terminal = Terminal::kNone;
    } else {
      throw ParseError("key '" + r.key_name("terminal") + "' must be \"flower\" or \"none\"", file,
                       line_of(*t), column_of(*t));
    }
  }
  a.branching_delay = r.get_int("branching_delay", 1, 0);
  const auto& units = as_array(r.require("units"), r.key_name("units"), file);
  for (std::size_t i = 0; i < units.size(); ++i) {
    const std::string p = path + ".units[" + std::to_string(i) + "]";
    a.units.push_back(read_run(as_table(units[i], p, file), p, file));
    std::vector<int> ax_lines;
    if (const auto* ax = units[i].as_table()->get("axillary")) {
      for (const auto& e : *ax->as_array()) ax_lines.push_back(line_of(e));
    }
    lines.axillary.push_back(std::move(ax_lines));
  }
  a.branching_probability = r.get_probability("branching_probability");
  a.growth_probability = r.get_probability("growth_probability");
  a.survival_probability = r.get_probability("survival_probability");
  a.geometry.leaf_life_span = r.get_nonnegative("leaf_life_span", 1.0);
  a.geometry.axis_life_span = r.get_nonnegative("axis_life_span", 0.0);
  a.geometry.pruning_period = r.get_nonnegative("pruning_period", 0.0);
  a.geometry.branching_angle_deg = r.get_any("branching_angle", 60.0);
  a.geometry.phyllotaxy_deg = r.get_any("phyllotaxy", 147.5);
  if (const toml::node* o = r.find("orientation")) {
    const auto s = o->value<std::string>();
    if (s == "orthotropic") {
      a.geometry.orientation = Orientation::kOrthotropic;
    } else if (s == "plagiotropic") {
      a.geometry.orientation = Orientation::kPlagiotropic;
    } else {
      throw ParseError(
          "key '" + r.key_name("orientation") + "' must be \"orthotropic\" or \"plagiotropic\"",
          file, line_of(*o), column_of(*o));
    }
  }
  a.geometry.straightening = r.get_double("straightening", 0.0, 0.0, 1.0, "a fraction in [0, 1]");
  a.geometry.internode_length_m = r.get_nonnegative("internode_length", 1.0);
  a.geometry.internode_radius_m = r.get_nonnegative("internode_radius", 0.05);
  a.geometry.radius_growth_m = r.get_nonnegative("radius_growth", 0.0);
  a.geometry.leaf_length_m = r.get_nonnegative("leaf_length", 0.3);
  if (const toml::node* s = r.find("leaf_on_surface")) {
    const auto v = s->value_exact<bool>();
    if (!v) {
      throw ParseError("key '" + r.key_name("leaf_on_surface") + "' must be true or false", file,
                       line_of(*s), column_of(*s));
    }
    a.geometry.leaf_on_surface = *v;
  }
  a.geometry.leaf_angle_increase_deg =
      r.get_double("leaf_angle_increase", 0.0, -180.0, 180.0, "an angle in [-180, 180]");
  a.geometry.leaf_opening_cycles = r.get_nonnegative("leaf_opening", 0.0);
  auto& f = a.functional;
  f.leaf_sink = r.get_nonnegative("leaf_sink", 1.0);
  f.internode_sink = r.get_nonnegative("internode_sink", 1.0);
  f.leaf_expansion = r.get_expansion("leaf_expansion");
  f.internode_expansion = r.get_expansion("internode_expansion");
  f.leaf_beta_a = r.get_positive("leaf_beta_a", 2.0);
  f.leaf_beta_b = r.get_positive("leaf_beta_b", 2.0);
  f.internode_beta_a = r.get_positive("internode_beta_a", 2.0);
  f.internode_beta_b = r.get_positive("internode_beta_b", 2.0);
  r.reject_unknown();
  return a;
}

Functional read_functional(const toml::table& table, const std::string& file) {
  TableReader r(table, "functional", file);
  Functional f;
  f.enabled = true;
  f.seed_biomass = r.get_nonnegative("seed_biomass", 1.0);
  f.resistance = r.get_positive("resistance", 1.0);
  f.projected_area = r.get_positive("projected_area", 1.0);
  f.extinction = r.get_nonnegative("extinction", 1.0);
  f.environment = r.get_nonnegative("environment", 1.0);
  f.specific_leaf_mass = r.get_positive("specific_leaf_mass", 1.0);
  f.ring_sink = r.get_nonnegative("ring_sink", 0.0);
  f.density = r.get_positive("density", 1.0);
  f.leaf_thickness = r.get_positive("leaf_thickness", 0.001);
  f.reference_length = r.get_positive("reference_length", 5.0);
  f.allometry_b = r.get_positive("allometry_b", 1.0);
  r.reject_unknown();
  return f;
}

}  // namespace

double metamer_birth(BirthDates mode, int cycle, int k, int n) {
  if (mode == BirthDates::kCycle || n <= 0) return cycle;
  return static_cast<double>(cycle - 1) + static_cast<double>(k) / static_cast<double>(n);
}

long birth_cycle(double birth) {
  // Dates a rounding step above an integer c still belong to cycle c.
  return static_cast<long>(std::ceil(birth - 1e-9));
}

bool PlantParams::stochastic() const {
  for (const auto& a : ages) {
    if (a.stochastic()) return true;
  }
  return false;
}

void PlantParams::validate() const {
  if (cycles < 0 || cycles > kMaxCycles) {
    throw ValueError("plant.cycles must be in [0, " + std::to_string(kMaxCycles) + "]");
  }
  if (ages.empty()) throw ValueError("a plant needs at least one [[age]]");
  const int p = static_cast<int>(ages.size());
  for (const auto& a : ages) {
    const std::string where = "age " + std::to_string(a.index);
    for (const int t : {a.functional.leaf_expansion, a.functional.internode_expansion}) {
      if (t < 1 || t > kMaxCycles) {
        throw ValueError(where + ": an expansion of " + std::to_string(t) +
                         " cycles, expected 1 to " + std::to_string(kMaxCycles));
      }
    }
    if (a.next_age != 0 && (a.next_age < a.index || a.next_age > p)) {
      throw ValueError(where + ": next_age " + std::to_string(a.next_age) +
                       " must be 0 or an age in [" + std::to_string(a.index) + ", " +
                       std::to_string(p) + "] (an apex never returns to a lower age)");
    }
    for (const auto& run : a.units) {
      for (const auto& b : run.axillary) {
        if (b.age < a.index || b.age > p) {
          throw ValueError(where + ": axillary age " + std::to_string(b.age) + " must be in [" +
                           std::to_string(a.index) + ", " + std::to_string(p) + "]");
        }
        if (b.age == a.index && age(b.age).branching_delay == 0) {
          throw ValueError(where + ": a bud of the same age needs branching_delay >= 1");
        }
      }
    }
  }
}

namespace {

// The [plant] table: cycles, seed and how birth dates are kept.
void read_plant_table(const toml::table& root, TableReader& top, const std::string& file,
                      PlantParams& params) {
  TableReader plant(as_table(top.require("plant"), "plant", file), "plant", file);
  params.cycles = plant.get_int("cycles", 0, 0, true);
  if (params.cycles > kMaxCycles) {
    throw ParseError("key 'plant.cycles' is " + std::to_string(params.cycles) +
                         ", expected at most " + std::to_string(kMaxCycles),
                     file, line_of(*root["plant"]["cycles"].node()));
  }
  params.seed = static_cast<std::uint64_t>(plant.get_int("seed", 1, 0));
  if (const toml::node* b = plant.find("birth_dates")) {
    const auto s = b->value<std::string>();
    if (s == "cycle") {
      params.birth_dates = BirthDates::kCycle;
    } else if (s == "continuous") {
      params.birth_dates = BirthDates::kContinuous;
    } else {
      throw ParseError("key 'plant.birth_dates' must be \"cycle\" or \"continuous\"", file,
                       line_of(*b), column_of(*b));
    }
  }
  plant.reject_unknown();
}

// Transitions checked here, with lines, before validate() repeats them without.
void check_age_transitions(const PlantParams& params, const std::vector<AgeLines>& lines,
                           const std::string& file) {
  const int count = static_cast<int>(params.ages.size());
  for (std::size_t i = 0; i < params.ages.size(); ++i) {
    const AgeParams& a = params.ages[i];
    const std::string p = "age[" + std::to_string(i) + "]";
    if (a.next_age != 0 && (a.next_age < a.index || a.next_age > count)) {
      throw ParseError("key '" + p + ".next_age' is " + std::to_string(a.next_age) +
                           ": an apex only moves to a higher physiological age (expected 0 or " +
                           std::to_string(a.index) + ".." + std::to_string(count) + ")",
                       file, lines[i].next_age);
    }
    for (std::size_t u = 0; u < a.units.size(); ++u) {
      for (std::size_t k = 0; k < a.units[u].axillary.size(); ++k) {
        const int q = a.units[u].axillary[k].age;
        if (q < a.index || q > count) {
          throw ParseError("key '" + p + ".units[" + std::to_string(u) + "].axillary[" +
                               std::to_string(k) + "].age' is " + std::to_string(q) +
                               ": a bud is never of a lower physiological age than its axis "
                               "(expected " +
                               std::to_string(a.index) + ".." + std::to_string(count) + ")",
                           file, lines[i].axillary[u][k]);
        }
      }
    }
  }
}

// The [[age]] tables, in order 1..P.
void read_age_tables(TableReader& top, const std::string& file, PlantParams& params) {
  const auto& ages = as_array(top.require("age"), "age", file);
  std::vector<AgeLines> lines(ages.size());
  for (std::size_t i = 0; i < ages.size(); ++i) {
    const std::string p = "age[" + std::to_string(i) + "]";
    AgeParams a = read_age(as_table(ages[i], p, file), p, file, lines[i]);
    if (a.index != static_cast<int>(i) + 1) {
      throw ParseError("key 'age[" + std::to_string(i) + "].index' is " + std::to_string(a.index) +
                           ", expected " + std::to_string(i + 1) + " (ages listed in order 1..P)",
                       file, lines[i].table);
    }
    params.ages.push_back(std::move(a));
  }
  check_age_transitions(params, lines, file);
}

// The [calibration] table: names of parameters that get_parameter() knows.
void read_calibration_table(const toml::node& c, const std::string& file, PlantParams& params) {
  TableReader cal(as_table(c, "calibration", file), "calibration", file);
  const auto& names = as_array(cal.require("parameters"), "calibration.parameters", file);
  for (const auto& n : names) {
    auto s = n.value<std::string>();
    if (!s) {
      throw ParseError("calibration.parameters must hold strings", file, line_of(n), column_of(n));
    }
    PlantParams probe = params;
    try {
      (void)get_parameter(probe, *s);
    } catch (const ValueError& e) {
      throw ParseError(e.message(), file, line_of(n), column_of(n));
    }
    params.calibration_parameters.push_back(*s);
  }
  cal.reject_unknown();
}

}  // namespace

PlantParams parse_plant_params(std::string_view toml_text, const std::string& source_name) {
  const toml::table root = parse_toml_text(toml_text, source_name);
  const std::string& file = source_name;
  TableReader top(root, "", file);
  PlantParams params;
  read_plant_table(root, top, file, params);
  read_age_tables(top, file, params);
  if (const toml::node* f = top.find("functional")) {
    params.functional = read_functional(as_table(*f, "functional", file), file);
  }
  if (const toml::node* c = top.find("calibration")) read_calibration_table(*c, file, params);
  top.reject_unknown();
  params.validate();
  return params;
}

PlantParams read_plant_params(const std::string& path) {
  return parse_plant_params(read_text_input_file(path), path);
}

namespace {

double* parameter_slot(PlantParams& params, const std::string& name) {
  auto& f = params.functional;
  if (name == "seed_biomass") return &f.seed_biomass;
  if (name == "resistance") return &f.resistance;
  if (name == "projected_area") return &f.projected_area;
  if (name == "extinction") return &f.extinction;
  if (name == "environment") return &f.environment;
  if (name == "specific_leaf_mass") return &f.specific_leaf_mass;
  if (name == "ring_sink") return &f.ring_sink;
  if (name.rfind("age.", 0) == 0) {
    const auto dot = name.find('.', 4);
    if (dot != std::string::npos) {
      int index = 0;
      try {
        index = std::stoi(name.substr(4, dot - 4));
      } catch (const std::exception&) {
        index = 0;
      }
      if (index >= 1 && index <= static_cast<int>(params.ages.size())) {
        auto& a = params.age(index).functional;
        const std::string key = name.substr(dot + 1);
        if (key == "leaf_sink") return &a.leaf_sink;
        if (key == "internode_sink") return &a.internode_sink;
        if (key == "leaf_beta_a") return &a.leaf_beta_a;
        if (key == "leaf_beta_b") return &a.leaf_beta_b;
        if (key == "internode_beta_a") return &a.internode_beta_a;
        if (key == "internode_beta_b") return &a.internode_beta_b;
      }
    }
  }
  throw ValueError("unknown calibration parameter '" + name +
                   "' (expected seed_biomass, resistance, projected_area, extinction, "
                   "environment, specific_leaf_mass, ring_sink or age.N.leaf_sink, "
                   "age.N.internode_sink, age.N.leaf_beta_a, age.N.leaf_beta_b, "
                   "age.N.internode_beta_a, age.N.internode_beta_b)");
}

}  // namespace

double get_parameter(const PlantParams& params, const std::string& name) {
  return *parameter_slot(const_cast<PlantParams&>(params), name);
}

void set_parameter(PlantParams& params, const std::string& name, double value) {
  *parameter_slot(params, name) = value;
}

}  // namespace fspm::greenlab
