// fspm distance | stats: compare trees (constrained edit distance) and groups of measurements
// (t-tests, Mann-Whitney U).
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/enum_option.hpp"
#include "cli/output.hpp"
#include "fspm/constrained_edit_distance.hpp"
#include "fspm/error.hpp"
#include "fspm/newick_format.hpp"
#include "fspm/number_column.hpp"
#include "fspm/number_text.hpp"
#include "fspm/statistics.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::cli {
namespace {

struct DistanceOptions {
  std::string a, b;
  EditCostKind cost = EditCostKind::kTopological;
  std::vector<std::string> attributes;
  std::optional<double> main_skeleton;
  AssignmentSolver solver = AssignmentSolver::kHungarian;
  bool mapping = false;
  bool json = false;
};

struct TTestOptions {
  std::string a, b;
  bool welch = false;
  bool paired = false;
  std::string column;
  Alternative alternative = Alternative::kTwoSided;
  double level = kDefaultConfidenceLevel;
  bool json = false;
};

struct MannWhitneyOptions {
  std::string a, b;
  std::string column;
  Alternative alternative = Alternative::kTwoSided;
  bool no_correction = false;
  bool json = false;
};

struct DescribeOptions {
  std::string file;
  std::string column;
  double level = kDefaultConfidenceLevel;
  bool json = false;
};

// A tree argument: a literal Newick string when it starts with '(' or ends with ';' and names
// no file (a one-node tree such as `10;`), else a tree file.
TreeGraph load_tree(const std::string& arg, const char* which, bool& is_newick) {
  std::error_code ec;
  const bool literal = !arg.empty() && (arg.front() == '(' ||
                                        (arg.back() == ';' && !std::filesystem::exists(arg, ec)));
  if (literal) {
    is_newick = true;
    return parse_newick(arg, std::string("<Newick argument ") + which + ">");
  }
  is_newick = tree_format_for(arg) == TreeFormat::kNewick;
  return read_tree_file(arg);
}

void run_distance(const DistanceOptions& o) {
  bool newick_a = false, newick_b = false;
  const TreeGraph a = load_tree(o.a, "A", newick_a);
  const TreeGraph b = load_tree(o.b, "B", newick_b);
  EditDistanceOptions opt;
  opt.cost = o.cost;
  opt.attributes = o.attributes;
  if (opt.cost == EditCostKind::kTopological && !o.attributes.empty()) {
    spdlog::warn(
        "--attr is ignored by the topological cost model (use --cost absolute or "
        "standardized)");
    opt.attributes.clear();
  }
  // Newick carries one number per node, the attribute "label": the natural default there.
  if (opt.attributes.empty() && opt.cost != EditCostKind::kTopological && newick_a && newick_b) {
    opt.attributes = {std::string(kNewickLabel)};
  }
  if (opt.attributes.empty()) opt.attributes = default_edit_attributes(opt.cost);
  opt.main_skeleton_radius_m = o.main_skeleton;
  opt.solver = o.solver;
  opt.with_mapping = o.mapping;
  const EditDistanceResult r = constrained_edit_distance(a, b, opt);
  if (o.json) {
    nlohmann::json j{{"distance", r.distance},
                     {"normalized_distance", r.normalized},
                     {"deletion_cost_a", r.deletion_cost_a},
                     {"insertion_cost_b", r.insertion_cost_b},
                     {"nodes_a", r.nodes_a},
                     {"nodes_b", r.nodes_b},
                     {"cost", std::string(edit_cost_kind_name(o.cost))},
                     {"attributes", opt.attributes}};
    if (o.main_skeleton) j["main_skeleton"] = *o.main_skeleton;
    if (o.mapping) {
      nlohmann::json pairs = nlohmann::json::array();
      for (const auto& [x, y] : r.mapping) pairs.push_back({x, y});
      j["mapping"] = pairs;
    }
    print_json(j);
    return;
  }
  // The normalized distance gives the raw one a scale: 0 identical, 1 nothing in common.
  std::cout << "distance: " << format_significant(r.distance) << '\n'
            << "normalized_distance: " << format_significant(r.normalized)
            << " (of deleting A and inserting B, "
            << format_significant(r.deletion_cost_a + r.insertion_cost_b) << ")\n"
            << "nodes_a: " << r.nodes_a << '\n'
            << "nodes_b: " << r.nodes_b << '\n';
  if (o.mapping) {
    std::cout << "mapping (node of A -> node of B):\n";
    for (const auto& [x, y] : r.mapping) std::cout << "  " << x << " -> " << y << '\n';
  }
}

// A sample from a file, with the file named in the error when it is too small.
std::vector<double> read_sample(const std::string& path, const std::string& column,
                                std::size_t minimum) {
  std::vector<double> v = read_number_column(path, column);
  if (v.size() < minimum) {
    throw ValueError("expected at least " + std::to_string(minimum) + " values, found " +
                         std::to_string(v.size()),
                     path);
  }
  return v;
}

nlohmann::json number_or_null(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

void run_ttest(const TTestOptions& o) {
  const auto a = read_sample(o.a, o.column, 2);
  const auto b = read_sample(o.b, o.column, 2);
  const Alternative alt = o.alternative;
  if (o.paired && a.size() != b.size()) {
    throw ValueError("paired t-test: " + o.a + " has " + std::to_string(a.size()) + " values but " +
                     o.b + " has " + std::to_string(b.size()));
  }
  const TTestResult r = o.paired  ? paired_t_test(a, b, alt, o.level)
                        : o.welch ? welch_t_test(a, b, alt, o.level)
                                  : student_t_test(a, b, alt, o.level);
  const char* test = o.paired ? "paired" : (o.welch ? "welch" : "student");
  const nlohmann::json j{
      {"test", test},
      {"alternative", std::string(alternative_name(o.alternative))},
      {"t", r.t},
      {"df", r.df},
      {"p", r.p},
      {"mean_a", r.mean_a},
      {"mean_b", r.mean_b},
      {"sd_a", r.sd_a},
      {"sd_b", r.sd_b},
      {"n_a", r.n_a},
      {"n_b", r.n_b},
      {"estimate", r.estimate},
      {"confidence_level", o.level},
      {"confidence_interval",
       {number_or_null(r.confidence_interval.low), number_or_null(r.confidence_interval.high)}},
      {"cohens_d", o.paired ? nlohmann::json(nullptr) : nlohmann::json(cohens_d(a, b))}};
  if (o.json) {
    print_json(j);
    return;
  }
  std::cout << test << " t-test (" << alternative_name(o.alternative) << ")\n";
  for (const char* key : {"t", "df", "p", "mean_a", "mean_b", "sd_a", "sd_b", "n_a", "n_b",
                          "estimate", "confidence_interval", "cohens_d"}) {
    if (j[key].is_null()) continue;
    std::cout << "  " << key << ": " << human_text(j[key]) << '\n';
  }
}

void run_mann_whitney(const MannWhitneyOptions& o) {
  const auto a = read_sample(o.a, o.column, 1);
  const auto b = read_sample(o.b, o.column, 1);
  const auto r = mann_whitney_u_test(a, b, o.alternative, !o.no_correction);
  const nlohmann::json j{{"test", "mann-whitney"},
                         {"alternative", std::string(alternative_name(o.alternative))},
                         {"u", r.u},
                         {"p", r.p},
                         {"exact", r.exact},
                         {"n_a", a.size()},
                         {"n_b", b.size()}};
  if (o.json) {
    print_json(j);
    return;
  }
  for (const char* key : {"u", "p", "exact", "n_a", "n_b"}) {
    std::cout << key << ": " << human_text(j[key]) << '\n';
  }
}

void run_describe(const DescribeOptions& o) {
  const auto v = read_sample(o.file, o.column, 2);
  const Interval ci = mean_confidence_interval(v, o.level);
  const nlohmann::json j{{"n", v.size()},
                         {"mean", mean(v)},
                         {"sd", standard_deviation(v)},
                         {"confidence_level", o.level},
                         {"confidence_interval", {ci.low, ci.high}}};
  if (o.json) {
    print_json(j);
    return;
  }
  for (const char* key : {"n", "mean", "sd", "confidence_interval"}) {
    std::cout << key << ": " << human_text(j[key]) << '\n';
  }
}

}  // namespace

void add_evaluation_commands(CLI::App& app) {
  auto d = std::make_shared<DistanceOptions>();
  CLI::App* dist = app.add_subcommand(
      "distance", "Constrained edit distance between two trees (Zhang; Ferraro and Godin)");
  dist->add_option("A", d->a, "Tree file (.tree, .treeb, .nwk, .mtg) or a Newick string '(...);'")
      ->required();
  dist->add_option("B", d->b, "Tree file (.tree, .treeb, .nwk, .mtg) or Newick string")->required();
  add_enum_option(dist, "--cost", d->cost, kEditCostKindNames, "Cost model");
  dist->add_option("--attr", d->attributes,
                   "Attributes compared, comma-separated (default: label for Newick, else "
                   "length,radius)")
      ->delimiter(',');
  dist->add_option("--main-skeleton", d->main_skeleton,
                   "Compare only nodes with radius above this thickness (m) and their ancestors")
      ->check(number_in(0, 1e300));
  add_enum_option(dist, "--solver", d->solver, kAssignmentSolverNames, "Forest matching");
  dist->add_flag("--mapping", d->mapping, "Also print the matched node pairs");
  dist->add_flag("--json", d->json, "Machine-readable JSON on stdout");
  dist->callback([d] { run_distance(*d); });

  CLI::App* stats = app.add_subcommand("stats", "Statistics over groups of measurements");
  stats->require_subcommand(1);
  const std::string file_help =
      "Text file with one number per line (a header line allowed), or a CSV file with --column";

  auto t = std::make_shared<TTestOptions>();
  CLI::App* tt = stats->add_subcommand("ttest", "Two-sample t-test (Student by default)");
  tt->add_option("A", t->a, file_help)->required();
  tt->add_option("B", t->b, file_help)->required();
  auto* welch = tt->add_flag("--welch", t->welch, "Welch's test (unequal variances)");
  auto* paired = tt->add_flag("--paired", t->paired, "Paired test on a_i - b_i");
  welch->excludes(paired);
  tt->add_option("--column", t->column, "CSV column name (the first row is the header)");
  add_enum_option(tt, "--alternative", t->alternative, kAlternativeNames,
                  "The alternative hypothesis about mean(A) - mean(B)");
  tt->add_option("--level", t->level, "Confidence level of the interval")->capture_default_str();
  tt->add_flag("--json", t->json, "Machine-readable JSON on stdout");
  tt->footer(
      "Input: one number per line, the first line may be a header, e.g.\n"
      "  dry_weight_g\n  4.17\n  5.58\n  ...\n"
      "or a CSV file whose column --column names. Example (Dobson's plant weights):\n"
      "  fspm stats ttest examples/stats/plant_growth_ctrl.csv "
      "examples/stats/plant_growth_trt2.csv --welch");
  tt->callback([t] { run_ttest(*t); });

  auto m = std::make_shared<MannWhitneyOptions>();
  CLI::App* mw = stats->add_subcommand("mannwhitney", "Mann-Whitney U (Wilcoxon rank-sum) test");
  mw->add_option("A", m->a, file_help)->required();
  mw->add_option("B", m->b, file_help)->required();
  mw->add_option("--column", m->column, "CSV column name (the first row is the header)");
  add_enum_option(mw, "--alternative", m->alternative, kAlternativeNames,
                  "The alternative hypothesis about A's location against B's");
  mw->add_flag("--no-correction", m->no_correction,
               "No continuity correction in the normal approximation");
  mw->add_flag("--json", m->json, "Machine-readable JSON on stdout");
  mw->callback([m] { run_mann_whitney(*m); });

  auto s = std::make_shared<DescribeOptions>();
  CLI::App* ds = stats->add_subcommand("describe", "Mean, standard deviation, confidence interval");
  ds->add_option("FILE", s->file, file_help)->required();
  ds->add_option("--column", s->column, "CSV column name (the first row is the header)");
  ds->add_option("--level", s->level, "Confidence level of the interval")->capture_default_str();
  ds->add_flag("--json", s->json, "Machine-readable JSON on stdout");
  ds->callback([s] { run_describe(*s); });
}

}  // namespace fspm::cli
