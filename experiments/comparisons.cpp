#include "experiments/comparisons.hpp"
#include "fspm/elapsed.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>

#include "experiments/report_notes.hpp"
#include "experiments/results_db.hpp"
#include "experiments/run_seed.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/edit_cost_model.hpp"
#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/input_file.hpp"
#include "fspm/memory_account.hpp"
#include "fspm/nesting_depth.hpp"
#include "fspm/number_text.hpp"
#include "fspm/p_value_text.hpp"
#include "fspm/statistics.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// FNV-1a, so that every comparison draws its pairs from its own stream.
std::uint64_t name_hash(const std::string& name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : name) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

bool matches(const RunRecord& r, const RunFilter& filter) {
  for (const auto& [name, value] : filter) {
    const auto it = r.parameters.find(name);
    if (it == r.parameters.end() || parameter_text(it->second) != parameter_text(value)) {
      return false;
    }
  }
  return true;
}

std::string group_label(const RunRecord& r, const std::vector<std::string>& within) {
  if (within.empty()) return "all";
  std::string label;
  for (const std::string& name : within) {
    const auto it = r.parameters.find(name);
    label += (label.empty() ? "" : ", ") + name + "=" +
             (it == r.parameters.end() ? std::string("-") : parameter_text(it->second));
  }
  return label;
}

const std::string* tree_file(const RunRecord& r) {
  for (const std::string& f : r.files) {
    if (file_kind_by_extension(f) == FileKind::kTreeText) return &f;
  }
  return nullptr;
}

struct PairJob {
  const RunRecord* a;
  const RunRecord* b;
};

// Pairs without reuse: the same filter on both sides pairs consecutive runs of one shuffled list;
// otherwise each run of the shuffled A list takes the next unused run of the shuffled B list.
std::vector<PairJob> draw_pairs(std::vector<const RunRecord*> a, std::vector<const RunRecord*> b,
                                bool same_set, std::size_t wanted, std::mt19937_64& rng) {
  std::vector<PairJob> pairs;
  const std::size_t limit = wanted == 0 ? std::numeric_limits<std::size_t>::max() : wanted;
  std::shuffle(a.begin(), a.end(), rng);
  if (same_set) {
    for (std::size_t i = 0; i + 1 < a.size() && pairs.size() < limit; i += 2) {
      pairs.push_back({a[i], a[i + 1]});
    }
    return pairs;
  }
  std::shuffle(b.begin(), b.end(), rng);
  std::set<std::size_t> used;
  std::size_t j = 0;
  for (const RunRecord* ra : a) {
    if (pairs.size() >= limit) break;
    if (used.contains(ra->run)) continue;
    while (j < b.size() && (used.contains(b[j]->run) || b[j]->run == ra->run)) ++j;
    if (j == b.size()) break;
    pairs.push_back({ra, b[j]});
    used.insert(ra->run);
    used.insert(b[j]->run);
    ++j;
  }
  return pairs;
}

std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// A number in a table for people: four significant digits (pairs.csv has every digit).
std::string number(double v) {
  if (!std::isfinite(v)) return "-";
  return format_significant(v);
}

}  // namespace

EditDistanceOptions distance_options(const DistanceSpec& spec) {
  EditDistanceOptions o;
  o.cost = spec.cost;
  o.attributes = spec.attributes;
  o.main_skeleton_radius_m = spec.main_skeleton_radius_m;
  return o;
}

ComparisonResults run_comparisons(const Experiment& x, const std::vector<RunRecord>& runs,
                                  const std::string& out_dir, std::size_t jobs) {
  ComparisonResults results;
  const EditDistanceOptions options = distance_options(x.distance);
  std::vector<PairJob> jobs_list;
  for (const ComparisonSpec& c : x.comparisons) {
    // Candidates per group, in run order (the shuffle is what randomizes).
    std::map<std::string, std::pair<std::vector<const RunRecord*>, std::vector<const RunRecord*>>>
        groups;
    for (const RunRecord& r : runs) {
      if (r.status != RunStatus::kOk || tree_file(r) == nullptr || !matches(r, c.where)) continue;
      const std::string g = group_label(r, c.within);
      if (matches(r, c.a)) groups[g].first.push_back(&r);
      if (matches(r, c.b)) groups[g].second.push_back(&r);
    }
    if (groups.empty()) {
      results.notes.push_back("comparison " + c.name +
                              ": no finished run with a kept tree matches");
    }
    const bool same_set = c.a == c.b;
    std::size_t group_index = 0;
    for (auto& [label, sides] : groups) {
      std::mt19937_64 rng(run_seed(x.seed ^ name_hash(c.name), group_index++));
      const std::vector<PairJob> pairs =
          draw_pairs(sides.first, sides.second, same_set, c.pairs, rng);
      if (c.pairs != 0 && pairs.size() < c.pairs) {
        results.notes.push_back("comparison " + c.name + " (" + label + "): only " +
                                std::to_string(pairs.size()) + " of " + std::to_string(c.pairs) +
                                " pairs without reusing a run");
      }
      for (const PairJob& p : pairs) {
        PairDistance d;
        d.comparison = c.name;
        d.group = label;
        d.run_a = p.a->run;
        d.run_b = p.b->run;
        d.seed_a = p.a->seed;
        d.seed_b = p.b->seed;
        results.pairs.push_back(d);
        jobs_list.push_back(p);
      }
    }
  }

  const auto t0 = std::chrono::steady_clock::now();
  const int threads = jobs == 0 ? tbb::this_task_arena::max_concurrency() : static_cast<int>(jobs);
  tbb::task_arena arena(threads);
  std::vector<std::string> errors(jobs_list.size());
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, jobs_list.size(), [&](std::size_t i) {
      // The pairs computed at once share the one memory limit (fspm/memory_account.hpp).
      const MemoryAccount account;
      try {
        const TreeGraph a =
            read_tree_file((fs::path(out_dir) / *tree_file(*jobs_list[i].a)).string());
        const TreeGraph b =
            read_tree_file((fs::path(out_dir) / *tree_file(*jobs_list[i].b)).string());
        const EditDistanceResult r = constrained_edit_distance(a, b, options);
        results.pairs[i].distance = r.distance;
        results.pairs[i].normalized = r.normalized;
        results.pairs[i].nodes_a = r.nodes_a;
        results.pairs[i].nodes_b = r.nodes_b;
      } catch (const std::exception& e) {
        errors[i] = e.what();
      }
    });
  });
  for (const std::string& e : errors) {
    if (!e.empty()) throw IoError("comparison: " + e);
  }
  results.seconds = seconds_since(t0);
  results.tests = comparison_ttests(x, results.pairs, &results.notes);
  return results;
}

std::vector<TTestRow> comparison_ttests(const Experiment& x, const std::vector<PairDistance>& pairs,
                                        std::vector<std::string>* notes) {
  // distances[comparison][group]
  std::map<std::string, std::map<std::string, std::vector<double>>> distances;
  for (const PairDistance& p : pairs) {
    distances[p.comparison][p.group].push_back(p.value(x.distance.tested));
  }
  std::vector<TTestRow> rows;
  for (const TTestSpec& spec : x.ttests) {
    for (const auto& [group, a] : distances[spec.a]) {
      const auto it = distances[spec.b].find(group);
      if (it == distances[spec.b].end() || a.size() < 2 || it->second.size() < 2) continue;
      const std::vector<double>& b = it->second;
      const Alternative alt = spec.alternative;
      TTestResult t;
      TTestRow row;
      try {
        t = spec.welch ? welch_t_test(a, b, alt) : student_t_test(a, b, alt);
        // The interval of the difference is two-sided whatever the test's alternative.
        const TTestResult both = spec.welch ? welch_t_test(a, b) : student_t_test(a, b);
        row.difference_low = both.confidence_interval.low;
        row.difference_high = both.confidence_interval.high;
        row.cohens_d = cohens_d(a, b);
      } catch (const ValueError& e) {
        row.difference_low = row.difference_high = row.cohens_d = std::nan("");
        // Constant groups (zero standard error): t and p are undefined, not an error of the run.
        t.t = t.df = t.p = std::nan("");
        t.mean_a = mean(a);
        t.mean_b = mean(b);
        t.sd_a = standard_deviation(a);
        t.sd_b = standard_deviation(b);
        t.n_a = a.size();
        t.n_b = b.size();
        if (notes != nullptr) {
          notes->push_back("t-test " + spec.a + " vs " + spec.b + " (" + group +
                           "): " + e.message());
        }
      }
      row.a = spec.a;
      row.b = spec.b;
      row.group = group;
      row.scale = x.distance.tested;
      row.welch = spec.welch;
      row.alternative = spec.alternative;
      row.alpha = spec.alpha;
      row.t = t.t;
      row.df = t.df;
      row.p = t.p;
      row.mean_a = t.mean_a;
      row.mean_b = t.mean_b;
      row.sd_a = t.sd_a;
      row.sd_b = t.sd_b;
      row.n_a = t.n_a;
      row.n_b = t.n_b;
      rows.push_back(row);
    }
  }
  // Holm over the whole family: with 18 tests at alpha = 0.05, about one would come out
  // significant by chance alone without it.
  std::vector<double> p;
  for (const TTestRow& r : rows) p.push_back(r.p);
  const std::vector<double> holm = holm_adjusted(p);
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i].p_holm = holm[i];
  return rows;
}

void write_comparisons(const ComparisonResults& results, const std::string& out_dir) {
  const fs::path dir(out_dir);
  write_file_atomically((dir / kPairsFile).string(), [&](std::ostream& out) {
    out.precision(17);
    out << "comparison,group,run_a,run_b,seed_a,seed_b,distance,normalized_distance,nodes_a,"
           "nodes_b\n";
    for (const PairDistance& p : results.pairs) {
      out << csv_text(p.comparison) << ',' << csv_text(p.group) << ',' << p.run_a << ',' << p.run_b
          << ',' << p.seed_a << ',' << p.seed_b << ',' << p.distance << ',' << p.normalized << ','
          << p.nodes_a << ',' << p.nodes_b << '\n';
    }
  });
  write_file_atomically((dir / kTTestsFile).string(), [&](std::ostream& out) {
    out.precision(17);
    out << "a,b,group,distance,test,alternative,t,df,p,alpha,significant,mean_a,sd_a,n_a,mean_b,sd_"
           "b,n_b,p_holm,difference_low,difference_high,cohens_d\n";
    for (const TTestRow& t : results.tests) {
      out << csv_text(t.a) << ',' << csv_text(t.b) << ',' << csv_text(t.group) << ','
          << distance_scale_name(t.scale) << ',' << (t.welch ? "welch" : "student") << ','
          << alternative_name(t.alternative) << ',' << t.t << ',' << t.df << ',' << t.p << ','
          << t.alpha << ',' << (t.significant() ? 1 : 0) << ',' << t.mean_a << ',' << t.sd_a << ','
          << t.n_a << ',' << t.mean_b << ',' << t.sd_b << ',' << t.n_b << ',' << t.p_holm << ','
          << t.difference_low << ',' << t.difference_high << ',' << t.cohens_d << '\n';
    }
  });
  json j;
  j["pairs"] = json::array();
  for (const PairDistance& p : results.pairs) {
    j["pairs"].push_back({{"comparison", p.comparison},
                          {"group", p.group},
                          {"run_a", p.run_a},
                          {"run_b", p.run_b},
                          {"seed_a", p.seed_a},
                          {"seed_b", p.seed_b},
                          {"distance", p.distance},
                          {"normalized_distance", p.normalized},
                          {"nodes_a", p.nodes_a},
                          {"nodes_b", p.nodes_b}});
  }
  j["notes"] = results.notes;
  j["seconds"] = results.seconds;
  write_file_atomically((dir / kComparisonsFile).string(),
                        [&](std::ostream& out) { out << j.dump(1) << '\n'; });
}

bool read_comparisons(const std::string& out_dir, ComparisonResults& results) {
  const fs::path path = fs::path(out_dir) / kComparisonsFile;
  std::error_code ec;
  if (!fs::exists(path, ec)) return false;
  const std::string text = read_input_file(path.string());
  check_json_depth(text, path.string());
  json j;
  try {
    j = json::parse(text);
    results = {};
    for (const json& p : j.at("pairs")) {
      PairDistance d;
      d.comparison = p.at("comparison").get<std::string>();
      d.group = p.at("group").get<std::string>();
      d.run_a = p.at("run_a").get<std::size_t>();
      d.run_b = p.at("run_b").get<std::size_t>();
      d.seed_a = p.at("seed_a").get<std::uint64_t>();
      d.seed_b = p.at("seed_b").get<std::uint64_t>();
      d.distance = p.at("distance").get<double>();
      d.normalized = p.at("normalized_distance").get<double>();
      d.nodes_a = p.at("nodes_a").get<std::size_t>();
      d.nodes_b = p.at("nodes_b").get<std::size_t>();
      results.pairs.push_back(std::move(d));
    }
    results.notes = j.at("notes").get<std::vector<std::string>>();
    results.seconds = j.at("seconds").get<double>();
  } catch (const json::exception& e) {
    throw ParseError(std::string("not a comparisons file of this fspm version (run `fspm compare` "
                                 "on its directory again): ") +
                         e.what(),
                     path.string());
  }
  return true;
}

ComparisonResults compare_results(const std::string& dir, std::size_t jobs) {
  const ResultsDb db(dir, ResultsDb::Mode::kRead);
  const Experiment x = parse_experiment(db.info().experiment_text, db.info().experiment_path);
  if (x.comparisons.empty()) {
    throw ValueError("the experiment of " + dir + " has no [[comparison]]",
                     db.info().experiment_path);
  }
  ComparisonResults results = run_comparisons(x, db.read_all(), dir, jobs);
  write_comparisons(results, dir);
  return results;
}

std::string comparisons_markdown(const Experiment& x, const ComparisonResults& results) {
  std::ostringstream md;
  // distances[group][comparison]
  std::map<std::string, std::map<std::string, std::vector<double>>> distances, raw;
  for (const PairDistance& p : results.pairs) {
    distances[p.group][p.comparison].push_back(p.value(x.distance.tested));
    raw[p.group][p.comparison].push_back(p.distance);
  }
  const bool normalized = x.distance.tested == DistanceScale::kNormalized;
  md << "## Comparisons\n\n"
     << (normalized ? "Normalized constrained edit distance" : "Constrained edit distance") << " ("
     << edit_cost_kind_name(x.distance.cost) << " costs";
  if (!x.distance.attributes.empty()) {
    md << " on";
    for (const std::string& a : x.distance.attributes) md << ' ' << a;
  }
  if (x.distance.main_skeleton_radius_m) {
    md << ", main skeleton: radius > " << number(*x.distance.main_skeleton_radius_m) << " m";
  }
  md << ") between pairs of runs, no run used twice within a comparison; per-pair values and "
        "both runs' seeds in `pairs.csv`, tests in `ttests.csv`.";
  if (normalized) {
    md << " The normalized distance divides the distance by the cost of deleting all of one tree "
          "and inserting all of the other: 0 for identical trees, 1 for trees with nothing in "
          "common, whatever their size; the t-tests compare it (`tested = \"raw\"` in "
          "`[distance]` tests the raw distance instead, whose mean is shown too).";
  }
  md << "\n\n";
  md << "| group | |";
  for (const ComparisonSpec& c : x.comparisons) md << ' ' << c.name << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < x.comparisons.size(); ++i) md << "---|";
  md << '\n';
  for (const auto& [group, by_comparison] : distances) {
    auto row = [&](const char* what, auto cell) {
      md << "| " << group << " | " << what << " |";
      for (const ComparisonSpec& c : x.comparisons) {
        const auto it = by_comparison.find(c.name);
        md << ' ' << (it == by_comparison.end() ? std::string("-") : cell(c.name, it->second))
           << " |";
      }
      md << '\n';
    };
    row("pairs",
        [](const std::string&, const std::vector<double>& v) { return std::to_string(v.size()); });
    row("mean", [](const std::string&, const std::vector<double>& v) { return number(mean(v)); });
    row("standard deviation", [](const std::string&, const std::vector<double>& v) {
      return v.size() > 1 ? number(standard_deviation(v)) : std::string("-");
    });
    if (normalized) {
      row("mean raw distance", [&](const std::string& name, const std::vector<double>&) {
        return number(mean(raw[group][name]));
      });
    }
    row("p-value", [&](const std::string& name, const std::vector<double>&) {
      std::string cell;
      for (const TTestRow& t : results.tests) {
        if (t.group == group && t.a == name) {
          cell += (cell.empty() ? "" : "; ") + format_p_value(t.p) + " vs " + t.b;
        }
      }
      return cell.empty() ? std::string(" ") : cell;
    });
  }
  if (!results.tests.empty()) {
    md << "\n### t-tests\n\nmean a - mean b with its 95 % confidence interval, Cohen's d, and p "
          "before and after Holm's correction over all "
       << results.tests.size()
       << " tests (Holm 1979); significance is judged on the corrected p.\n\n"
       << "| group | a | b | test | mean a - mean b [95 % CI] | Cohen's d | t | df | p | Holm p | "
          "significant at alpha |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const TTestRow& t : results.tests) {
      md << "| " << t.group << " | " << t.a << " | " << t.b << " | "
         << (t.welch ? "Welch" : "Student") << ", " << alternative_name(t.alternative) << " | "
         << number(t.mean_a - t.mean_b) << " [" << number(t.difference_low) << ", "
         << number(t.difference_high) << "] | " << number(t.cohens_d) << " | " << number(t.t)
         << " | " << number(t.df) << " | " << format_p_value(t.p) << " | "
         << format_p_value(t.p_holm) << " | " << (t.significant_holm() ? "yes" : "no") << " ("
         << number(t.alpha) << ") |\n";
    }
  }
  md << notes_markdown(results.notes);
  return md.str();
}

}  // namespace fspm::experiments
