#include "greenlab/functional.hpp"

#include <cmath>

#include "fspm/error.hpp"

namespace fspm::greenlab {

OrganTable organ_counts(const CompressedTreeGraph& graph, int ages, int cycles) {
  OrganTable t(static_cast<std::size_t>(ages) + 1,
               std::vector<double>(static_cast<std::size_t>(cycles) + 1, 0.0));
  for (const auto& r : graph.records()) {
    const auto c = birth_cycle(r.birth);
    if (r.physiological_age < 1 || r.physiological_age > ages || c < 1 || c > cycles) continue;
    t[r.physiological_age][static_cast<std::size_t>(c)] += static_cast<double>(r.multiplicity);
  }
  return t;
}

std::vector<double> beta_expansion(int duration, double a, double b) {
  std::vector<double> f(static_cast<std::size_t>(std::max(duration, 1)), 0.0);
  const double t_total = static_cast<double>(f.size());
  double sum = 0.0;
  for (std::size_t t = 0; t < f.size(); ++t) {
    const double x = (static_cast<double>(t) + 0.5) / t_total;
    f[t] = std::pow(x, a - 1.0) * std::pow(1.0 - x, b - 1.0);
    sum += f[t];
  }
  for (double& v : f) v = sum > 0.0 ? v / sum : 1.0 / t_total;
  return f;
}

Gl1Result run_gl1(const PlantParams& params, const OrganTable& counts, int cycles) {
  const auto& fp = params.functional;
  const int n_ages = static_cast<int>(params.ages.size());
  const auto nc = static_cast<std::size_t>(cycles) + 1;
  Gl1Result res;
  res.production.assign(nc, 0.0);
  res.demand.assign(nc, 0.0);
  res.leaf_area.assign(nc, 0.0);
  res.leaf_mass.assign(static_cast<std::size_t>(n_ages) + 1, std::vector<double>(nc, 0.0));
  res.internode_mass = res.leaf_mass;
  res.ring_mass.assign(nc, 0.0);
  res.production[0] = fp.seed_biomass;

  std::vector<std::vector<double>> f_leaf(static_cast<std::size_t>(n_ages) + 1);
  std::vector<std::vector<double>> f_int(static_cast<std::size_t>(n_ages) + 1);
  for (int p = 1; p <= n_ages; ++p) {
    const auto& a = params.age(p).functional;
    f_leaf[static_cast<std::size_t>(p)] =
        beta_expansion(a.leaf_expansion, a.leaf_beta_a, a.leaf_beta_b);
    f_int[static_cast<std::size_t>(p)] =
        beta_expansion(a.internode_expansion, a.internode_beta_a, a.internode_beta_b);
  }
  std::vector<double> ring_increment(nc, 0.0);
  double internodes_before = 0.0;  // internodes born before the current cycle
  for (std::size_t n = 1; n < nc; ++n) {
    const double q = res.production[n - 1];
    // Demand D(n) of the organs expanding in cycle n.
    double demand = 0.0;
    for (int p = 1; p <= n_ages; ++p) {
      const auto up = static_cast<std::size_t>(p);
      const auto& a = params.age(p).functional;
      for (std::size_t c = 1; c <= n; ++c) {
        const double count = counts[up][c];
        if (count == 0.0) continue;
        const std::size_t t = n - c;
        if (t < f_leaf[up].size()) demand += count * a.leaf_sink * f_leaf[up][t];
        if (t < f_int[up].size()) demand += count * a.internode_sink * f_int[up][t];
      }
    }
    const double ring_demand = internodes_before > 0.0 ? fp.ring_sink : 0.0;
    demand += ring_demand;
    res.demand[n] = demand;
    if (demand > 0.0) {
      const double ratio = q / demand;
      for (int p = 1; p <= n_ages; ++p) {
        const auto up = static_cast<std::size_t>(p);
        const auto& a = params.age(p).functional;
        for (std::size_t c = 1; c <= n; ++c) {
          const std::size_t t = n - c;
          if (t < f_leaf[up].size()) res.leaf_mass[up][c] += a.leaf_sink * f_leaf[up][t] * ratio;
          if (t < f_int[up].size()) {
            res.internode_mass[up][c] += a.internode_sink * f_int[up][t] * ratio;
          }
        }
      }
      if (ring_demand > 0.0) ring_increment[n] = ring_demand * ratio / internodes_before;
    }
    // Green leaf area after cycle n.
    double area = 0.0;
    for (int p = 1; p <= n_ages; ++p) {
      const auto up = static_cast<std::size_t>(p);
      const double span = params.age(p).geometry.leaf_life_span;
      for (std::size_t c = 1; c <= n; ++c) {
        if (span > 0.0 && static_cast<double>(n - c) >= span) continue;
        area += counts[up][c] * res.leaf_mass[up][c] / fp.specific_leaf_mass;
      }
    }
    res.leaf_area[n] = area;
    res.production[n] = fp.environment * (fp.projected_area / fp.resistance) *
                        (1.0 - std::exp(-fp.extinction * area / fp.projected_area));
    for (int p = 1; p <= n_ages; ++p) internodes_before += counts[static_cast<std::size_t>(p)][n];
  }
  // Rings of an internode born in cycle c: every increment after c.
  double acc = 0.0;
  for (std::size_t c = nc; c-- > 1;) {
    res.ring_mass[c] = acc;
    acc += ring_increment[c];
  }
  return res;
}

Gl1Result apply_functional(const PlantParams& params, CompressedTreeGraph& graph) {
  const int cycles = static_cast<int>(std::lround(graph.final_age));
  const int n_ages = static_cast<int>(params.ages.size());
  const OrganTable counts = organ_counts(graph, n_ages, cycles);
  Gl1Result res = run_gl1(params, counts, cycles);
  const double density = params.functional.density;
  for (RecordId id = 0; id < graph.size(); ++id) {
    const auto& r = graph.record(id);
    const auto c = birth_cycle(r.birth);
    if (r.physiological_age < 1 || r.physiological_age > n_ages || c < 1 || c > cycles) continue;
    const auto p = static_cast<std::size_t>(r.physiological_age);
    const auto uc = static_cast<std::size_t>(c);
    graph.set_volumes(id, res.internode_mass[p][uc] / density, res.ring_mass[uc] / density,
                      res.leaf_mass[p][uc] / density);
  }
  return res;
}

}  // namespace fspm::greenlab
