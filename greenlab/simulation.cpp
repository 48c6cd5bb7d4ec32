#include "greenlab/simulation.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>

#include "fspm/dcheck.hpp"
#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/functional.hpp"

namespace fspm::greenlab {

double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

namespace {

// Where a substructure starts, or, when it holds no metamer, what its apex became.
struct Start {
  RecordId first = kNoRecord;
  ApexState state = ApexState::kNone;
};

// Record ids and axillary offsets are 32-bit (fspm/compressed_tree_graph.hpp), metamer ranks int.
constexpr std::uint64_t kMaxRecords = std::numeric_limits<std::int32_t>::max();

class Factorizer {
 public:
  Factorizer(const PlantParams& params, std::mt19937_64& rng, int cycles)
      : params_(params), rng_(rng), cycles_(cycles) {
    const int p = static_cast<int>(params.ages.size());
    // An age is deterministic when neither it nor any age it can reach draws at random. Reachable
    // ages are never lower (Jaeger's j, k >= i), so one pass from the top age down suffices.
    deterministic_.assign(static_cast<std::size_t>(p) + 1, true);
    for (int i = p; i >= 1; --i) {
      const AgeParams& a = params.age(i);
      bool det = !a.stochastic();
      FSPM_DCHECK(a.next_age == 0 || a.next_age >= i, "validate() keeps transitions upward");
      if (a.next_age > i) det = det && deterministic_[static_cast<std::size_t>(a.next_age)];
      for (const auto& run : a.units) {
        for (const auto& b : run.axillary) {
          FSPM_DCHECK(b.age >= i, "validate() keeps axillary ages upward");
          if (b.age > i) det = det && deterministic_[static_cast<std::size_t>(b.age)];
          // A bud's own branching probability decides whether it grows.
          det = det && params.age(b.age).branching_probability >= 1.0;
        }
      }
      deterministic_[static_cast<std::size_t>(i)] = det;
    }
  }

  // S(p, t): the axis grown by an apex of age p that becomes active at cycle t, with `remaining`
  // cycles left at this age (its duration when it enters the age).
  Start build(int p, int t, int remaining) {
    if (t > cycles_) return {kNoRecord, ApexState::kBud};
    if (!deterministic_[static_cast<std::size_t>(p)]) return grow_stochastic(p, t);
    // Two deterministic apices of the same age active from the same cycle have the same future
    // when they change age on the same date, or both after the last cycle: the remaining time is
    // capped by the cycles left, so an age that outlives the simulation gives one substructure
    // per (age, cycle) and the graph stays linear in cycles x ages.
    const int capped = std::min(remaining, cycles_ - t + 1);
    const std::uint64_t key = (static_cast<std::uint64_t>(p) << 48) |
                              (static_cast<std::uint64_t>(t) << 24) |
                              static_cast<std::uint64_t>(capped);
    if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    const Start s = grow_unit(p, t, capped);
    memo_.emplace(key, s);
    return s;
  }

  CompressedTreeGraph& graph() { return graph_; }

 private:
  bool draw(double probability) { return probability >= 1.0 || uniform01(rng_) < probability; }

  // Appends the metamers of one growth unit of age p born in cycle c to the chain first..last.
  void grow_metamers(const AgeParams& a, int p, int c, RecordId& first, RecordId& last) {
    std::vector<RecordId> refs;
    std::uint64_t metamers = 0;
    std::uint64_t buds = 0;  // at most: every bud grows
    for (const auto& run : a.units) {
      const auto count = static_cast<std::uint64_t>(run.count);
      metamers += count;
      for (const auto& b : run.axillary) buds += count * static_cast<std::uint64_t>(b.count);
    }
    check_unit_memory(metamers, buds);
    const auto n = static_cast<int>(metamers);  // below kMaxRecords
    int rank = 0;                               // metamers of the unit so far
    for (const auto& run : a.units) {
      for (int m = 0; m < run.count; ++m) {
        ++rank;
        refs.clear();
        for (const auto& b : run.axillary) {
          const AgeParams& bud = params_.age(b.age);
          for (int k = 0; k < b.count; ++k) {
            if (!draw(bud.branching_probability)) continue;  // stays dormant
            const Start s = build(b.age, c + bud.branching_delay, bud.duration);
            if (s.first != kNoRecord) refs.push_back(s.first);
          }
        }
        CompressedRecord r;
        r.physiological_age = static_cast<std::uint16_t>(p);
        r.birth = metamer_birth(params_.birth_dates, c, rank, n);
        const RecordId id = graph_.add_record(r, refs);
        if (last != kNoRecord) {
          graph_.set_successor(last, id);
        } else {
          first = id;
        }
        last = id;
      }
    }
  }

  // A growth unit of 10^9 metamers, or of as many buds, would take tens of GiB before anything
  // else sees the graph: its records and references are checked against the memory budget
  // before they are added. At its peak the graph is held about three times over (a vector
  // doubling its capacity, then the renumbered copy of renumber()).
  void check_unit_memory(std::uint64_t metamers, std::uint64_t buds) const {
    const double records = static_cast<double>(graph_.size()) + static_cast<double>(metamers);
    const double refs =
        static_cast<double>(graph_.axillary_refs().size()) + static_cast<double>(buds);
    const std::string what = "the compressed plant of " + count_text(records) + " records and " +
                             count_text(refs) + " axillary references";
    check_memory(3.0 * (records * sizeof(CompressedRecord) + refs * sizeof(RecordId)), what);
    if (records > kMaxRecords || refs > kMaxRecords) {
      throw ValueError(what + ": more than the " + std::to_string(kMaxRecords) +
                       " a compressed plant holds (unit counts too large)");
    }
  }

  static std::string count_text(double n) {
    return std::to_string(static_cast<std::uint64_t>(std::min(n, 1e19)));
  }

  // What follows the last growth unit at age p when the apex leaves it at cycle c.
  Start transition(const AgeParams& a, int c) {
    if (c > cycles_) return {kNoRecord, ApexState::kBud};
    if (a.next_age == 0) {
      return {kNoRecord, a.terminal == Terminal::kFlower ? ApexState::kFlower : ApexState::kNone};
    }
    return build(a.next_age, c, params_.age(a.next_age).duration);
  }

  Start link(RecordId first, RecordId last, const Start& next) {
    if (last == kNoRecord) return next;
    if (next.first != kNoRecord) {
      graph_.set_successor(last, next.first);
    } else {
      graph_.set_apex(last, next.state);
    }
    return {first, ApexState::kNone};
  }

  // Deterministic: one growth unit in cycle t, then the shared rest of the axis.
  Start grow_unit(int p, int t, int remaining) {
    const AgeParams& a = params_.age(p);
    RecordId first = kNoRecord;
    RecordId last = kNoRecord;
    grow_metamers(a, p, t, first, last);
    const Start next = remaining > 1 ? build(p, t + 1, remaining - 1) : transition(a, t + 1);
    return link(first, last, next);
  }

  // GL2: the apex survives each cycle with survival_probability and grows with
  // growth_probability; its duration counts from its first growth unit.
  Start grow_stochastic(int p, int t) {
    const AgeParams& a = params_.age(p);
    RecordId first = kNoRecord;
    RecordId last = kNoRecord;
    int first_unit = -1;
    int c = t;
    while (c <= cycles_) {
      if (!draw(a.survival_probability)) return link(first, last, {kNoRecord, ApexState::kNone});
      if (draw(a.growth_probability)) {
        if (first_unit < 0) first_unit = c;
        grow_metamers(a, p, c, first, last);
      }
      ++c;
      if (first_unit >= 0 && c - first_unit >= a.duration)
        return link(first, last, transition(a, c));
    }
    return link(first, last, {kNoRecord, ApexState::kBud});
  }

  const PlantParams& params_;
  std::mt19937_64& rng_;
  int cycles_;
  std::vector<bool> deterministic_;
  std::unordered_map<std::uint64_t, Start> memo_;
  CompressedTreeGraph graph_;
};

// Renumbers the records depth first from the root, successor before laterals (Jaeger's tables),
// dropping records no instance reaches.
CompressedTreeGraph renumber(const CompressedTreeGraph& g) {
  CompressedTreeGraph out;
  if (g.root() == kNoRecord) return out;
  const std::size_t n = g.size();
  std::vector<RecordId> new_id(n, kNoRecord);
  std::vector<RecordId> order;
  order.reserve(n);
  std::vector<RecordId> stack{g.root()};
  while (!stack.empty()) {
    const RecordId id = stack.back();
    stack.pop_back();
    if (new_id[id] != kNoRecord) continue;
    new_id[id] = static_cast<RecordId>(order.size());
    order.push_back(id);
    const auto ax = g.axillaries(id);
    for (std::size_t k = ax.size(); k-- > 0;) {
      if (new_id[ax[k]] == kNoRecord) stack.push_back(ax[k]);
    }
    const RecordId s = g.record(id).successor;
    if (s != kNoRecord && new_id[s] == kNoRecord) stack.push_back(s);
  }
  out.reserve(order.size(), g.axillary_refs().size());
  std::vector<RecordId> refs;
  for (RecordId old : order) {
    CompressedRecord r = g.record(old);
    if (r.successor != kNoRecord) r.successor = new_id[r.successor];
    refs.clear();
    for (RecordId a : g.axillaries(old)) refs.push_back(new_id[a]);
    out.add_record(r, refs);
  }
  out.set_root(0);
  out.final_age = g.final_age;
  out.birth_date = g.birth_date;
  out.metadata = g.metadata;
  return out;
}

}  // namespace

CompressedTreeGraph simulate_compressed(const PlantParams& params, std::mt19937_64& rng,
                                        int cycles) {
  params.validate();
  if (cycles < 0) cycles = params.cycles;
  Factorizer f(params, rng, cycles);
  const Start root = f.build(1, 1, params.age(1).duration);
  CompressedTreeGraph& raw = f.graph();
  raw.set_root(root.first);
  raw.final_age = cycles;
  raw.birth_date = 0.0;
  raw.metadata = geometry_metadata(params);
  CompressedTreeGraph g = renumber(raw);
  g.compute_multiplicities();
  if (params.functional.enabled) apply_functional(params, g);
  return g;
}

CompressedTreeGraph simulate_compressed(const PlantParams& params, int cycles) {
  std::mt19937_64 rng(params.seed);
  return simulate_compressed(params, rng, cycles);
}

OrganCounts count_organs(const CompressedTreeGraph& graph) {
  OrganCounts c;
  const ReconstructionParams geo = ReconstructionParams::from_metadata(graph.metadata);
  const double now = graph.birth_date + graph.final_age;
  for (const auto& r : graph.records()) {
    c.metamers += r.multiplicity;
    c.metamers_by_age[r.physiological_age] += r.multiplicity;
    const double span = geo.age(r.physiological_age).leaf_life_span;
    // Jaeger 3.2.1: a leaf is alive while birth + life span is after the present date.
    if (span <= 0.0 || r.birth + span > now) c.leaves += r.multiplicity;
    if (r.apex == ApexState::kFlower) c.flowers += r.multiplicity;
    if (r.apex == ApexState::kBud) c.buds += r.multiplicity;
  }
  return c;
}

}  // namespace fspm::greenlab
