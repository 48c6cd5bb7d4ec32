#pragma once
// A GreenLab plant description: the dual-scale automaton (physiological ages, growth units made
// of metamers with axillary buds, age transitions), its GL2 probabilities, the geometry used at
// reconstruction and the GL1 source-sink parameters. Read from TOML (docs/greenlab.md).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fspm::greenlab {

// Buds carried at the axil of one metamer: `count` buds of physiological age `age`.
struct AxillaryBuds {
  int age = 0;
  int count = 0;
};

// One run of identical metamers in a growth unit (Zhao 2003: a micro-state).
struct MetamerRun {
  int count = 0;
  std::vector<AxillaryBuds> axillary;
};

enum class Terminal : std::uint8_t { kNone = 0, kFlower = 1 };
enum class Orientation : std::uint8_t { kOrthotropic = 0, kPlagiotropic = 1 };
// When the metamers of a growth unit appear. kCycle: all at the end of their cycle (birth date
// c). kContinuous: one after another through the cycle, as a continuous-time simulator produces
// them (Jaeger 4.2: time and aging attributes in floating point), metamer k of n at c - 1 + k/n.
enum class BirthDates : std::uint8_t { kCycle = 0, kContinuous = 1 };

// Organ-level GL1 parameters of one physiological age (Yan et al. 2004).
struct AgeFunctional {
  double leaf_sink = 1.0;
  double internode_sink = 1.0;
  int leaf_expansion = 1;       // cycles T_o of the expansion function
  int internode_expansion = 1;  // cycles
  double leaf_beta_a = 2.0;     // beta law shape a_o
  double leaf_beta_b = 2.0;
  double internode_beta_a = 2.0;
  double internode_beta_b = 2.0;
};

// Life spans and geometry of one physiological age, what the reconstruction needs (Jaeger
// 3.1.2-3.1.3, 3.2.1); a compressed graph carries them in its metadata (geometry_metadata).
struct AgeGeometry {
  double leaf_life_span = 1.0;  // cycles; 0 = never falls
  double axis_life_span = 0.0;  // cycles; 0 = never dies
  double pruning_period = 0.0;  // cycles a dead organ stays on the plant (Jaeger 3.2.1)
  double branching_angle_deg = 60.0;
  double phyllotaxy_deg = 147.5;
  Orientation orientation = Orientation::kOrthotropic;
  double straightening = 0.0;  // orthotropic: fraction of the heading turned up per metamer
  double internode_length_m = 1.0;
  double internode_radius_m = 0.05;
  double radius_growth_m = 0.0;  // radius gained per cycle of age when no GL1 volumes exist
  double leaf_length_m = 0.3;
  // Leaves (Jaeger 3.1.3): origin pushed from the axis centre line to its surface, and the
  // insertion angle increased over the branching angle, eased in over the leaf's first cycles.
  bool leaf_on_surface = false;
  double leaf_angle_increase_deg = 0.0;
  double leaf_opening_cycles = 0.0;  // 0: the increase applies from birth

  bool plagiotropic() const { return orientation == Orientation::kPlagiotropic; }
};

// One physiological age (a macro-state of the dual-scale automaton).
struct AgeParams {
  int index = 0;
  int duration = 1;  // cycles at this age, counted from the first growth unit
  int next_age = 0;  // 0: the apex stops and leaves `terminal`
  Terminal terminal = Terminal::kNone;
  int branching_delay = 1;  // cycles between a bud of this age's creation and its first unit
  std::vector<MetamerRun> units;
  double branching_probability = 1.0;  // GL2
  double growth_probability = 1.0;     // GL2
  double survival_probability = 1.0;   // GL2
  AgeGeometry geometry;
  AgeFunctional functional;

  bool stochastic() const {
    return branching_probability < 1.0 || growth_probability < 1.0 || survival_probability < 1.0;
  }
};

// Plant-level GL1 parameters (Yan et al. 2004, Jaeger annex for the allometry).
struct Functional {
  bool enabled = false;
  double seed_biomass = 1.0;        // Q(0)
  double resistance = 1.0;          // r
  double projected_area = 1.0;      // S_p
  double extinction = 1.0;          // k
  double environment = 1.0;         // E
  double specific_leaf_mass = 1.0;  // e: leaf mass per unit area
  double ring_sink = 0.0;           // p_ring: plant-level sink of secondary growth
  double density = 1.0;             // mass per volume of wood and leaves
  double leaf_thickness = 0.001;    // volume / area of a leaf
  double reference_length = 5.0;    // H_ref
  double allometry_b = 1.0;         // b
};

// Deeper simulations would exhaust the stack of the recursive factorization.
inline constexpr int kMaxCycles = 10000;

struct PlantParams {
  int cycles = 10;
  std::uint64_t seed = 1;
  BirthDates birth_dates = BirthDates::kCycle;
  std::vector<AgeParams> ages;  // ages[i].index == i + 1
  Functional functional;
  std::vector<std::string> calibration_parameters;  // names for `fspm greenlab fit`

  const AgeParams& age(int index) const { return ages[static_cast<std::size_t>(index - 1)]; }
  AgeParams& age(int index) { return ages[static_cast<std::size_t>(index - 1)]; }
  bool stochastic() const;
  // Throws ValueError when the description is inconsistent (transitions to lower ages, ...).
  void validate() const;
};

// Birth date of metamer k (1..n) of a growth unit of n metamers grown in cycle c: c, or
// c - 1 + k/n for continuous birth dates (the cycle spans the dates (c - 1, c]).
double metamer_birth(BirthDates mode, int cycle, int k, int n);
// The cycle whose dates (c - 1, c] hold a birth date: c for both kinds of birth dates.
long birth_cycle(double birth);

// Parses a plant description. Errors name the key and the line of `source_name`.
PlantParams parse_plant_params(std::string_view toml_text, const std::string& source_name = {});
PlantParams read_plant_params(const std::string& path);

// Reads and writes named numeric parameters ("resistance", "age.2.leaf_sink", ...) used by the
// calibration. Throws ValueError for an unknown name.
double get_parameter(const PlantParams& params, const std::string& name);
void set_parameter(PlantParams& params, const std::string& name, double value);

}  // namespace fspm::greenlab
