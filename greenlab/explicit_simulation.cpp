#include "greenlab/explicit_simulation.hpp"

#include "greenlab/simulation.hpp"

namespace fspm::greenlab {
namespace {

struct Apex {
  int age;
  int active_from;           // first cycle it may grow in
  int first_unit = -1;       // cycle of its first growth unit at this age
  std::int64_t last = -1;    // last metamer of its axis, or -1 before the first
  std::int64_t bearer = -1;  // metamer bearing it as a lateral (for the first metamer)
  std::size_t slot = 0;      // index among the bearer's laterals
  bool alive = true;
};

bool draw(std::mt19937_64& rng, double p) { return p >= 1.0 || uniform01(rng) < p; }

}  // namespace

ExplicitPlant simulate_explicit(const PlantParams& params, std::mt19937_64& rng, int cycles) {
  params.validate();
  if (cycles < 0) cycles = params.cycles;
  ExplicitPlant plant;
  auto& m = plant.metamers;
  std::vector<Apex> apices{{1, 1}};
  for (int c = 1; c <= cycles; ++c) {
    // Apices created during this cycle with no branching delay grow in it too (index loop).
    for (std::size_t i = 0; i < apices.size(); ++i) {
      if (!apices[i].alive || apices[i].active_from > c) continue;
      const AgeParams& a = params.age(apices[i].age);
      if (!draw(rng, a.survival_probability)) {
        apices[i].alive = false;
        continue;
      }
      if (draw(rng, a.growth_probability)) {
        if (apices[i].first_unit < 0) apices[i].first_unit = c;
        int n = 0;
        for (const auto& run : a.units) n += run.count;
        int rank = 0;  // metamers of the unit so far
        for (const auto& run : a.units) {
          for (int k = 0; k < run.count; ++k) {
            const auto id = static_cast<std::int64_t>(m.size());
            const double birth = metamer_birth(params.birth_dates, c, ++rank, n);
            m.push_back({apices[i].age, birth, -1, {}, ApexState::kNone});
            if (apices[i].last >= 0) {
              m[static_cast<std::size_t>(apices[i].last)].successor = id;
            } else if (apices[i].bearer >= 0) {
              m[static_cast<std::size_t>(apices[i].bearer)].laterals[apices[i].slot] = id;
            }
            apices[i].last = id;
            for (const auto& b : run.axillary) {
              const AgeParams& bud = params.age(b.age);
              for (int j = 0; j < b.count; ++j) {
                if (!draw(rng, bud.branching_probability)) continue;
                auto& lat = m[static_cast<std::size_t>(id)].laterals;
                Apex child{b.age, c + bud.branching_delay};
                child.bearer = id;
                child.slot = lat.size();
                lat.push_back(-1);
                apices.push_back(child);  // may reallocate: apices[i] re-read below
              }
            }
          }
        }
      }
      Apex& ap = apices[i];
      if (ap.first_unit >= 0 && c + 1 - ap.first_unit >= a.duration && c + 1 <= cycles) {
        if (a.next_age == 0) {
          if (ap.last >= 0 && a.terminal == Terminal::kFlower) {
            m[static_cast<std::size_t>(ap.last)].apex = ApexState::kFlower;
          }
          ap.alive = false;
        } else {
          ap.age = a.next_age;
          ap.active_from = c + 1;
          ap.first_unit = -1;
        }
      }
    }
  }
  for (const Apex& ap : apices) {
    if (ap.alive && ap.last >= 0) m[static_cast<std::size_t>(ap.last)].apex = ApexState::kBud;
  }
  // Buds that never grew leave no lateral.
  for (auto& x : m) std::erase(x.laterals, -1);
  return plant;
}

std::vector<CanonicalMetamer> canonical_sequence(const ExplicitPlant& plant) {
  std::vector<CanonicalMetamer> out;
  if (plant.metamers.empty()) return out;
  std::vector<std::pair<std::int64_t, int>> stack{{0, 0}};
  while (!stack.empty()) {
    const auto [id, order] = stack.back();
    stack.pop_back();
    const auto& x = plant.metamers[static_cast<std::size_t>(id)];
    out.push_back({x.age, x.birth, order, x.apex, x.laterals.size(), x.successor >= 0});
    for (std::size_t k = x.laterals.size(); k-- > 0;) stack.push_back({x.laterals[k], order + 1});
    if (x.successor >= 0) stack.push_back({x.successor, order});
  }
  return out;
}

std::vector<CanonicalMetamer> canonical_sequence(const CompressedTreeGraph& graph) {
  std::vector<CanonicalMetamer> out;
  if (graph.root() == kNoRecord) return out;
  std::vector<std::pair<RecordId, int>> stack{{graph.root(), 0}};
  while (!stack.empty()) {
    const auto [id, order] = stack.back();
    stack.pop_back();
    const auto& r = graph.record(id);
    const auto ax = graph.axillaries(id);
    out.push_back(
        {r.physiological_age, r.birth, order, r.apex, ax.size(), r.successor != kNoRecord});
    for (std::size_t k = ax.size(); k-- > 0;) stack.push_back({ax[k], order + 1});
    if (r.successor != kNoRecord) stack.push_back({r.successor, order});
  }
  return out;
}

}  // namespace fspm::greenlab
