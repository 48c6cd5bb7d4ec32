#pragma once
// The comparisons of an experiment (comparison_spec.hpp) carried out on its finished runs: pairs
// drawn without reuse (deterministically from the experiment seed), the constrained edit distance
// of every pair from the kept trees, and t-tests between groups of distances (Pirk 4.5.4).
// The t-tests compare the normalized distance unless the experiment's [distance] says
// tested = "raw". Results go to DIR/pairs.csv (one row per pair, with both runs' seeds, the raw
// and the normalized distance), DIR/ttests.csv and
// DIR/comparisons.json (what `fspm report` reads).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/run_record.hpp"
#include "fspm/constrained_edit_distance.hpp"

namespace fspm::experiments {

inline constexpr const char* kPairsFile = "pairs.csv";
inline constexpr const char* kTTestsFile = "ttests.csv";
inline constexpr const char* kComparisonsFile = "comparisons.json";

struct PairDistance {
  std::string comparison;
  std::string group;  // "preset=A" (the `within` values), "all" without `within`
  std::size_t run_a = 0, run_b = 0;
  std::uint64_t seed_a = 0, seed_b = 0;
  double distance = 0.0;
  double normalized = 0.0;  // distance / (cost of deleting all of A and inserting all of B)
  std::size_t nodes_a = 0, nodes_b = 0;  // nodes compared
  // The value tests and tables compare.
  double value(DistanceScale scale) const {
    return scale == DistanceScale::kRaw ? distance : normalized;
  }
};

struct TTestRow {
  std::string a, b;  // comparison names
  std::string group;
  DistanceScale scale = DistanceScale::kNormalized;  // which distance was tested
  bool welch = false;
  Alternative alternative = Alternative::kTwoSided;
  double alpha = 0.05;
  double t = 0.0, df = 0.0, p = 1.0;
  double mean_a = 0.0, sd_a = 0.0, mean_b = 0.0, sd_b = 0.0;
  std::size_t n_a = 0, n_b = 0;
  // Effect size: mean_a - mean_b with its two-sided 95 % confidence interval (of the test's kind,
  // Student or Welch) and Cohen's d (pooled standard deviation); NaN where undefined.
  double difference_low = 0.0, difference_high = 0.0;
  double cohens_d = 0.0;
  // p after Holm's correction over every t-test of the experiment (all groups: one family).
  double p_holm = 1.0;
  bool significant() const { return p < alpha; }  // false for a NaN p
  bool significant_holm() const { return p_holm < alpha; }
};

struct ComparisonResults {
  std::vector<PairDistance> pairs;  // comparison (file order), group, pair order
  std::vector<TTestRow> tests;
  std::vector<std::string> notes;  // e.g. fewer pairs than requested
  double seconds = 0.0;            // wall clock of the distances
};

// The distance options of an experiment's [distance] table.
EditDistanceOptions distance_options(const DistanceSpec& spec);

// Draws the pairs and computes their distances on `jobs` threads (0: one per hardware thread),
// then the t-tests. Needs the runs' kept trees under `out_dir`. Throws IoError for a missing tree
// file, ValueError for an unusable distance setting.
ComparisonResults run_comparisons(const Experiment& experiment, const std::vector<RunRecord>& runs,
                                  const std::string& out_dir, std::size_t jobs = 0);

// The t-tests of the experiment over the given pairs (run_comparisons calls it). A test over
// constant groups has NaN t and p, with a note.
std::vector<TTestRow> comparison_ttests(const Experiment& experiment,
                                        const std::vector<PairDistance>& pairs,
                                        std::vector<std::string>* notes = nullptr);

// Writes pairs.csv, ttests.csv and comparisons.json into `out_dir` (each atomically).
void write_comparisons(const ComparisonResults& results, const std::string& out_dir);
// Reads comparisons.json; false when `out_dir` has none.
bool read_comparisons(const std::string& out_dir, ComparisonResults& results);

// The comparisons of the experiment whose result database is in `dir` (its stored text, read
// back): run_comparisons over the recorded runs, then write_comparisons. Throws ValueError when
// the experiment has no [[comparison]].
ComparisonResults compare_results(const std::string& dir, std::size_t jobs = 0);

// Table 4.1 of Pirk in markdown: per group, the mean, standard deviation and p-values of the
// comparisons; then one row per t-test.
std::string comparisons_markdown(const Experiment& experiment, const ComparisonResults& results);

}  // namespace fspm::experiments
