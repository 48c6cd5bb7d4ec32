#pragma once
// GL1 source-sink functioning (de Reffye et al. 2003; Yan et al. 2004): biomass production from
// green leaf area, allocation to organs by sink strength times a beta-law expansion function,
// rings spread over the internodes by number. Organs of one physiological age born in one cycle
// are identical, so everything is computed per (age, birth cycle) and multiplied by the organ
// counts the compressed graph gives.
#include <cstdint>
#include <vector>

#include "fspm/compressed_tree_graph.hpp"
#include "greenlab/plant_params.hpp"

namespace fspm::greenlab {

// Metamers per physiological age and birth cycle: counts[p][c], p = 1..P, c = 1..cycles
// (index 0 unused). A metamer born at a fractional date (continuous birth dates) counts in the
// cycle that holds it, birth_cycle(birth): the functioning stays per cycle.
using OrganTable = std::vector<std::vector<double>>;
OrganTable organ_counts(const CompressedTreeGraph& graph, int ages, int cycles);

// Normalized beta law over an expansion of T cycles: f(t) = g(t) / sum g, t = 0..T-1,
// g(t) = ((t + 0.5) / T)^(a - 1) (1 - (t + 0.5) / T)^(b - 1).
std::vector<double> beta_expansion(int duration, double a, double b);

struct Gl1Result {
  std::vector<double> production;  // Q(n), n = 0..cycles (Q(0) = seed biomass)
  std::vector<double> demand;      // D(n), n = 1..cycles (index 0 unused)
  std::vector<double> leaf_area;   // green leaf area S(n) after cycle n, n = 0..cycles
  OrganTable leaf_mass;            // [p][c] one leaf's mass at the end
  OrganTable internode_mass;       // [p][c] one internode's pith mass at the end
  std::vector<double> ring_mass;   // [c] rings of one internode born in cycle c, at the end
};

// Runs cycles 1..N: cycle n shares Q(n-1) among the organs expanding in n,
//   dq_o(n) = p_o f_o(n - c_o) Q(n-1) / D(n),
// then Q(n) = E (S_p / r) (1 - exp(-k S(n) / S_p)) from the green leaf area S(n).
Gl1Result run_gl1(const PlantParams& params, const OrganTable& counts, int cycles);

// Runs GL1 on the graph's organ counts and stores pith, ring and leaf volumes (mass / density)
// in every record.
Gl1Result apply_functional(const PlantParams& params, CompressedTreeGraph& graph);

}  // namespace fspm::greenlab
