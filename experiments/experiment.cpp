#include "experiments/experiment.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include "fspm/closest_name.hpp"
#include "fspm/toml_text.hpp"

#include "experiments/metrics.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;

// Sweeps beyond this many runs are almost certainly a typo (a range step of 1e-9, ...).
constexpr double kMaxRuns = 1.0e9;

// The same limit for the file's runs and for a --replicates override: `prefix` names the option.
void check_run_count(double runs, const std::string& prefix, const std::string& path) {
  if (runs > kMaxRuns) {
    char count[32];
    std::snprintf(count, sizeof count, "%.0f", runs);
    throw ValueError(prefix + "the experiment has " + count + " runs, more than the limit of " +
                         std::to_string(static_cast<std::int64_t>(kMaxRuns)),
                     path, prefix.empty() ? 1 : 0);
  }
}

class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  static int line_of(const toml::node& node) { return static_cast<int>(node.source().begin.line); }

  [[noreturn]] void fail(const std::string& key, const toml::node& node,
                         const std::string& what) const {
    throw ValueError(key + ": " + what, path_, line_of(node),
                     static_cast<int>(node.source().begin.column));
  }

  void only_keys(const std::string& table_name, const toml::table& table,
                 std::initializer_list<std::string_view> allowed) const {
    for (auto&& [key, node] : table) {
      bool known = false;
      for (std::string_view a : allowed) known = known || key.str() == a;
      if (!known) {
        const std::vector<std::string> names(allowed.begin(), allowed.end());
        throw ValueError(unknown_key_message(qualified(table_name, key.str()), key.str(), names),
                         path_, line_of(node), static_cast<int>(node.source().begin.column));
      }
    }
  }

  static std::string qualified(const std::string& table, std::string_view key) {
    return table.empty() ? std::string(key) : table + "." + std::string(key);
  }

  const toml::table* table(const toml::table& root, const std::string& name, bool required) const {
    const toml::node* node = root.get(name);
    if (node == nullptr) {
      if (required) throw ValueError("missing table [" + name + "]", path_, 1);
      return nullptr;
    }
    if (!node->is_table()) fail(name, *node, "expected a table");
    return node->as_table();
  }

  std::string string(const std::string& key, const toml::node& node) const {
    if (!node.is_string()) fail(key, node, "expected a string");
    return node.value<std::string>().value();
  }

  std::int64_t integer(const std::string& key, const toml::node& node, std::int64_t min) const {
    if (!node.is_integer()) fail(key, node, "expected an integer");
    const std::int64_t v = node.value<std::int64_t>().value();
    if (v < min) fail(key, node, "must be at least " + std::to_string(min));
    return v;
  }

  double number(const std::string& key, const toml::node& node) const {
    if (!node.is_number()) fail(key, node, "expected a number");
    // toml++ gives no double for an integer that a double does not hold exactly
    // (3333333333333333338): take the nearest one.
    const std::optional<double> d = node.value<double>();
    const double v = d ? *d : static_cast<double>(node.value<std::int64_t>().value_or(0));
    if (!std::isfinite(v)) fail(key, node, "must be finite");
    return v;
  }

  ParameterValue scalar(const std::string& key, const toml::node& node) const {
    if (node.is_integer()) return node.value<std::int64_t>().value();
    if (node.is_floating_point()) return number(key, node);
    if (node.is_boolean()) return static_cast<std::int64_t>(node.value<bool>().value() ? 1 : 0);
    if (node.is_string()) return node.value<std::string>().value();
    fail(key, node, "expected a number, a boolean or a string");
  }

  const toml::array& array(const std::string& key, const toml::node& node, std::size_t size) const {
    if (!node.is_array()) fail(key, node, "expected an array");
    const toml::array& a = *node.as_array();
    if (size != 0 && a.size() != size) {
      fail(key, node, "expected an array of " + std::to_string(size) + " numbers");
    }
    return a;
  }

  // The values of one sweep axis are held in memory (the grid is not): checked before they are.
  void check_values_memory(const std::string& key, const toml::node& node, double count) const {
    try {
      check_memory(
          count * sizeof(ParameterValue),
          "a sweep axis of " + std::to_string(static_cast<std::int64_t>(count)) + " values");
    } catch (const MemoryLimitError& e) {
      throw MemoryLimitError(key + ": " + e.message(), path_, line_of(node),
                             static_cast<int>(node.source().begin.column));
    }
  }

  std::vector<ParameterValue> axis_values(const std::string& key, const toml::node& node) const {
    std::vector<ParameterValue> values;
    if (node.is_array()) {
      for (const toml::node& v : *node.as_array()) values.push_back(scalar(key, v));
      if (values.empty()) fail(key, node, "an empty list sweeps nothing");
      return values;
    }
    if (!node.is_table()) {
      fail(key, node,
           "expected a list of values or a table {range|linspace|logspace|values = ...}");
    }
    const toml::table& t = *node.as_table();
    if (t.size() != 1) {
      fail(key, node, "expected exactly one of range, linspace, logspace, values");
    }
    std::string kind;
    const toml::node* spec_node = nullptr;
    for (auto&& [k, v] : t) {
      kind = std::string(k.str());
      spec_node = &v;
    }
    const toml::node& spec = *spec_node;
    const std::string where = key + "." + kind;
    if (kind == "values") return axis_values(key, spec);
    if (kind == "range") {
      if (!spec.is_array() || spec.as_array()->size() < 2 || spec.as_array()->size() > 3) {
        fail(where, spec, "expected [start, stop] or [start, stop, step]");
      }
      const toml::array& a = *spec.as_array();
      bool all_integers = true;
      for (const toml::node& v : a) all_integers = all_integers && v.is_integer();
      const double start = number(where, *a.get(0));
      const double stop = number(where, *a.get(1));
      const double step = a.size() == 3 ? number(where, *a.get(2)) : 1.0;
      if (step == 0.0) fail(where, spec, "step must not be 0");
      // Half-open like Python's range: start, start + step, ... while before stop.
      const double count = std::ceil((stop - start) / step - 1e-9);
      if (!(count >= 1.0)) {
        fail(where, spec, "empty range: stop must lie after start in the direction of step");
      }
      if (count > kMaxRuns) fail(where, spec, "range has too many values");
      check_values_memory(where, spec, count);
      values.reserve(static_cast<std::size_t>(count));
      for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
        if (all_integers) {
          values.emplace_back(static_cast<std::int64_t>(start) +
                              static_cast<std::int64_t>(i) * static_cast<std::int64_t>(step));
        } else {
          values.emplace_back(start + static_cast<double>(i) * step);
        }
      }
      return values;
    }
    if (kind == "linspace" || kind == "logspace") {
      const toml::array& a = array(where, spec, 3);
      const double first = number(where, *a.get(0));
      const double last = number(where, *a.get(1));
      const std::int64_t n = integer(where + "[3]", *a.get(2), 1);
      if (static_cast<double>(n) > kMaxRuns) fail(where, spec, "too many values");
      check_values_memory(where, spec, static_cast<double>(n));
      values.reserve(static_cast<std::size_t>(n));
      const bool log = kind == "logspace";
      if (log && (first <= 0.0 || last <= 0.0)) {
        fail(where, spec, "logspace end points must be positive");
      }
      for (std::int64_t i = 0; i < n; ++i) {
        const double f = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
        double v = log ? std::exp(std::log(first) + f * (std::log(last) - std::log(first)))
                       : first + f * (last - first);
        if (i == n - 1 && n > 1) v = last;  // exact end point despite rounding
        if (i == 0) v = first;
        values.emplace_back(v);
      }
      return values;
    }
    fail(where, spec, "unknown sweep kind (expected range, linspace, logspace or values)");
  }

  SampledParameter sampled(const std::string& key, const std::string& name,
                           const toml::node& node) const {
    if (!node.is_table() || node.as_table()->size() != 1) {
      fail(key, node, "expected a table with one of uniform, loguniform, integers = [low, high]");
    }
    std::string kind;
    const toml::node* spec_node = nullptr;
    for (auto&& [k, v] : *node.as_table()) {
      kind = std::string(k.str());
      spec_node = &v;
    }
    const toml::node& spec = *spec_node;
    const std::string where = key + "." + kind;
    SampledParameter p;
    p.name = name;
    p.line = line_of(node);
    if (kind == "loguniform") {
      p.log_scale = true;
    } else if (kind == "integers") {
      p.integer = true;
    } else if (kind != "uniform") {
      fail(where, spec, "unknown distribution (expected uniform, loguniform or integers)");
    }
    const toml::array& a = array(where, spec, 2);
    if (p.integer) {
      p.low =
          static_cast<double>(integer(where, *a.get(0), std::numeric_limits<std::int64_t>::min()));
      p.high =
          static_cast<double>(integer(where, *a.get(1), std::numeric_limits<std::int64_t>::min()));
    } else {
      p.low = number(where, *a.get(0));
      p.high = number(where, *a.get(1));
    }
    if (!(p.low <= p.high)) fail(where, spec, "low must not exceed high");
    if (p.log_scale && p.low <= 0.0) fail(where, spec, "loguniform bounds must be positive");
    return p;
  }

  std::string resolve(const std::string& key, const toml::node& node) const {
    const std::string given = string(key, node);
    if (given.empty()) fail(key, node, "must not be empty");
    fs::path p(given);
    if (p.is_relative() && path_ != "<string>") p = fs::path(path_).parent_path() / p;
    std::error_code ec;
    if (!fs::is_regular_file(p, ec)) {
      // Relative paths are the experiment file's, not the working directory's: say where it looked.
      throw IoError(key + ": no such file '" + given + "' (looked for " +
                        fs::absolute(p, ec).lexically_normal().string() +
                        ": relative paths are read from the experiment file's folder; copy the "
                        "file along or give an absolute path)",
                    path_, line_of(node));
    }
    return p.lexically_normal().string();
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

std::vector<std::string> string_list(const Reader& r, const std::string& key,
                                     const toml::node& node) {
  std::vector<std::string> out;
  for (const toml::node& v : r.array(key, node, 0)) out.push_back(r.string(key, v));
  return out;
}

// A table of parameter values naming parameters of the experiment.
RunFilter run_filter(const Reader& r, const std::string& key, const toml::node& node,
                     const Experiment& x) {
  if (!node.is_table())
    r.fail(key, node, "expected a table of parameter values, e.g. { set = \"T\" }");
  RunFilter filter;
  for (auto&& [k, v] : *node.as_table()) {
    const std::string name(k.str());
    if (!x.parameter_lines.contains(name)) {
      r.fail(key + "." + name, v, "not a parameter of this experiment (fixed, swept or sampled)");
    }
    filter[name] = r.scalar(key + "." + name, v);
  }
  return filter;
}

std::vector<std::string> parameter_names(const Reader& r, const std::string& key,
                                         const toml::node& node, const Experiment& x) {
  std::vector<std::string> names = string_list(r, key, node);
  for (const std::string& name : names) {
    if (!x.parameter_lines.contains(name)) {
      r.fail(key, node, "'" + name + "' is not a parameter of this experiment");
    }
  }
  return names;
}

const toml::array& table_array(const Reader& r, const toml::table& root, const std::string& name) {
  static const toml::array kEmpty;
  const toml::node* node = root.get(name);
  if (node == nullptr) return kEmpty;
  if (!node->is_array_of_tables())
    r.fail(name, *node, "expected an array of tables [[" + name + "]]");
  return *node->as_array();
}

// A name of `names` (in order `kinds`), or a failure at `node` listing them.
template <typename Kind, typename Kinds>
Kind one_of(const Reader& r, const std::string& key, const toml::node& node, const Kinds& kinds,
            std::string_view (*name_of)(Kind)) {
  const std::string given = r.string(key, node);
  std::string list;
  for (Kind k : kinds) {
    if (name_of(k) == given) return k;
    list += (list.empty() ? "" : ", ") + std::string(name_of(k));
  }
  r.fail(key, node, "unknown value '" + given + "' (expected one of: " + list + ")");
}

// [distance]: how kept trees are compared.
void parse_distance(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table* d = r.table(root, "distance", false);
  if (d == nullptr) return;
  r.only_keys("distance", *d, {"cost", "attributes", "main_skeleton_radius_m", "tested"});
  if (const toml::node* n = d->get("cost")) {
    x.distance.cost = one_of(r, "distance.cost", *n, kEditCostKinds, edit_cost_kind_name);
  }
  if (const toml::node* n = d->get("tested")) {
    x.distance.tested = one_of(r, "distance.tested", *n, kDistanceScales, distance_scale_name);
  }
  if (const toml::node* n = d->get("attributes")) {
    x.distance.attributes = string_list(r, "distance.attributes", *n);
  }
  if (const toml::node* n = d->get("main_skeleton_radius_m")) {
    const double v = r.number("distance.main_skeleton_radius_m", *n);
    if (v < 0.0) r.fail("distance.main_skeleton_radius_m", *n, "must not be negative");
    x.distance.main_skeleton_radius_m = v;
  }
}

// [[comparison]]: named pairs of run filters.
void parse_comparison_tables(const Reader& r, const toml::table& root, Experiment& x) {
  for (const toml::node& node : table_array(r, root, "comparison")) {
    const toml::table& t = *node.as_table();
    r.only_keys("comparison", t, {"name", "a", "b", "where", "within", "pairs"});
    ComparisonSpec c;
    c.line = Reader::line_of(node);
    const toml::node* name = t.get("name");
    if (name == nullptr) throw ValueError("comparison.name: missing", x.path, c.line);
    c.name = r.string("comparison.name", *name);
    for (const ComparisonSpec& other : x.comparisons) {
      if (other.name == c.name) r.fail("comparison.name", *name, "given twice");
    }
    for (const char* side : {"a", "b"}) {
      const toml::node* n = t.get(side);
      if (n == nullptr) {
        throw ValueError(
            "comparison." + std::string(side) + ": missing (a filter such as { set = \"T\" })",
            x.path, c.line);
      }
      (side[0] == 'a' ? c.a : c.b) = run_filter(r, "comparison." + std::string(side), *n, x);
    }
    if (const toml::node* n = t.get("where")) c.where = run_filter(r, "comparison.where", *n, x);
    if (const toml::node* n = t.get("within")) {
      c.within = parameter_names(r, "comparison.within", *n, x);
    }
    if (const toml::node* n = t.get("pairs")) {
      c.pairs = static_cast<std::size_t>(r.integer("comparison.pairs", *n, 1));
    }
    x.comparisons.push_back(std::move(c));
  }
}

// [[ttest]]: two comparisons' distances against each other.
void parse_ttest_tables(const Reader& r, const toml::table& root, Experiment& x) {
  for (const toml::node& node : table_array(r, root, "ttest")) {
    const toml::table& t = *node.as_table();
    r.only_keys("ttest", t, {"a", "b", "welch", "alternative", "alpha"});
    TTestSpec test;
    test.line = Reader::line_of(node);
    for (const char* side : {"a", "b"}) {
      const toml::node* n = t.get(side);
      if (n == nullptr) {
        throw ValueError("ttest." + std::string(side) + ": missing (the name of a comparison)",
                         x.path, test.line);
      }
      const std::string name = r.string("ttest." + std::string(side), *n);
      bool known = false;
      for (const ComparisonSpec& c : x.comparisons) known = known || c.name == name;
      if (!known)
        r.fail("ttest." + std::string(side), *n, "no [[comparison]] named '" + name + "'");
      (side[0] == 'a' ? test.a : test.b) = name;
    }
    if (const toml::node* n = t.get("welch")) {
      if (!n->is_boolean()) r.fail("ttest.welch", *n, "expected true or false");
      test.welch = n->value<bool>().value();
    }
    if (const toml::node* n = t.get("alternative")) {
      test.alternative = one_of(r, "ttest.alternative", *n, kAlternatives, alternative_name);
    }
    if (const toml::node* n = t.get("alpha")) {
      test.alpha = r.number("ttest.alpha", *n);
      if (!(test.alpha > 0.0 && test.alpha < 1.0)) r.fail("ttest.alpha", *n, "must lie in (0, 1)");
    }
    x.ttests.push_back(std::move(test));
  }
}

// `metric` named at `node` must be among the recorded metrics.
void require_recorded(const Reader& r, const std::string& key, const toml::node& node,
                      const Experiment& x, const std::string& metric) {
  if (std::find(x.metrics.begin(), x.metrics.end(), metric) == x.metrics.end()) {
    r.fail(key, node, "'" + metric + "' is not recorded (add it to outputs.metrics)");
  }
}

// [[table]]: summary tables of metrics.
void parse_summary_tables(const Reader& r, const toml::table& root, Experiment& x) {
  for (const toml::node& node : table_array(r, root, "table")) {
    const toml::table& t = *node.as_table();
    r.only_keys("table", t, {"title", "where", "by", "metrics"});
    SummaryTableSpec s;
    s.line = Reader::line_of(node);
    if (const toml::node* n = t.get("title")) s.title = r.string("table.title", *n);
    if (const toml::node* n = t.get("where")) s.where = run_filter(r, "table.where", *n, x);
    if (const toml::node* n = t.get("by")) s.by = parameter_names(r, "table.by", *n, x);
    const toml::node* m = t.get("metrics");
    if (m == nullptr) throw ValueError("table.metrics: missing", x.path, s.line);
    s.metrics = string_list(r, "table.metrics", *m);
    for (const std::string& metric : s.metrics) require_recorded(r, "table.metrics", *m, x, metric);
    x.tables.push_back(std::move(s));
  }
}

// [report]: the text and renders of fspm report.
void parse_report_table(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table* rep = r.table(root, "report", false);
  if (rep == nullptr) return;
  r.only_keys("report", *rep,
              {"renders", "render_by", "render_where", "render_metric", "about", "html"});
  if (const toml::node* n = rep->get("about")) x.about = r.string("report.about", *n);
  if (const toml::node* n = rep->get("html")) {
    if (!n->is_boolean()) r.fail("report.html", *n, "expected true or false");
    x.report_html = n->value<bool>().value();
  }
  if (const toml::node* n = rep->get("renders")) {
    x.render.renders = static_cast<std::size_t>(r.integer("report.renders", *n, 0));
  }
  if (const toml::node* n = rep->get("render_by")) {
    x.render.by = parameter_names(r, "report.render_by", *n, x);
    x.render.by_given = true;
  }
  if (const toml::node* n = rep->get("render_where")) {
    x.render.where = run_filter(r, "report.render_where", *n, x);
  }
  if (const toml::node* n = rep->get("render_metric")) {
    x.render.metric = r.string("report.render_metric", *n);
    require_recorded(r, "report.render_metric", *n, x, x.render.metric);
  }
}

// [distance], [[comparison]], [[ttest]], [[table]], [report] (docs/experiments.md).
void parse_comparisons(const Reader& r, const toml::table& root, Experiment& x) {
  parse_distance(r, root, x);
  parse_comparison_tables(r, root, x);
  parse_ttest_tables(r, root, x);
  parse_summary_tables(r, root, x);
  parse_report_table(r, root, x);
  // Comparisons read the runs' trees back, so they are kept.
  if (!x.comparisons.empty() &&
      std::find(x.keep.begin(), x.keep.end(), KeptFile::kTree) == x.keep.end()) {
    x.keep.push_back(KeptFile::kTree);
  }
}

// [experiment]: name, seed, replicates, description.
void parse_experiment_table(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table& exp = *r.table(root, "experiment", true);
  r.only_keys("experiment", exp, {"name", "seed", "replicates", "description"});
  if (const toml::node* n = exp.get("name")) {
    x.name = r.string("experiment.name", *n);
  } else {
    throw ValueError("experiment.name: missing (every experiment needs a name)", r.path(),
                     Reader::line_of(exp));
  }
  if (const toml::node* n = exp.get("seed")) {
    x.seed = static_cast<std::uint64_t>(r.integer("experiment.seed", *n, 0));
  }
  if (const toml::node* n = exp.get("replicates")) {
    x.replicates = static_cast<std::size_t>(r.integer("experiment.replicates", *n, 1));
  }
  if (const toml::node* n = exp.get("description")) {
    x.description = r.string("experiment.description", *n);
  }
}

// [model]: kind and the files it reads.
void parse_model_table(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table& model = *r.table(root, "model", true);
  r.only_keys("model", model, {"kind", "file", "view", "scene"});
  const toml::node* kind_node = model.get("kind");
  if (kind_node == nullptr) {
    throw ValueError("model.kind: missing (" + model_kind_names() + ")", r.path(),
                     Reader::line_of(model));
  }
  const std::string kind = r.string("model.kind", *kind_node);
  x.model_kind_line = Reader::line_of(*kind_node);
  const std::optional<ModelKind> known = find_model_kind(kind);
  if (!known) {
    std::vector<std::string> names;
    for (ModelKind k : kModelKinds) names.emplace_back(model_kind_name(k));
    throw ValueError("model.kind: unknown kind '" + kind + "'" + closest_name_hint(kind, names),
                     r.path(), x.model_kind_line);
  }
  x.model_kind = *known;
  if (const toml::node* n = model.get("file")) {
    x.model_file = r.resolve("model.file", *n);
    x.model_file_line = Reader::line_of(*n);
  }
  if (const toml::node* n = model.get("view")) x.model_view = r.resolve("model.view", *n);
  if (const toml::node* n = model.get("scene")) x.model_scene = r.resolve("model.scene", *n);
}

// Records that the parameter `name` is given at `node`: a parameter is fixed, swept or sampled,
// once.
void claim_parameter(const Reader& r, Experiment& x, const std::string& name,
                     const toml::node& node) {
  if (name.empty()) r.fail("parameter", node, "empty parameter name");
  if (!x.parameter_lines.emplace(name, Reader::line_of(node)).second) {
    r.fail(name, node,
           "given twice (line " + std::to_string(x.parameter_lines[name]) +
               "): a parameter is either fixed, swept or sampled");
  }
}

// [parameters]: fixed values.
void parse_fixed_parameters(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table* fixed = r.table(root, "parameters", false);
  if (fixed == nullptr) return;
  for (auto&& [key, node] : *fixed) {
    const std::string name(key.str());
    claim_parameter(r, x, name, node);
    x.fixed[name] = r.scalar("parameters." + name, node);
  }
}

// [sweep]: the grid's axes in file order.
void parse_sweep_table(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table* sweep = r.table(root, "sweep", false);
  if (sweep == nullptr) return;
  for (auto&& [key, node] : *sweep) {
    const std::string name(key.str());
    claim_parameter(r, x, name, node);
    x.sweep.push_back({name, r.axis_values("sweep." + name, node), Reader::line_of(node)});
  }
  // toml++ iterates tables in key order; the file order is what users expect for the grid.
  std::stable_sort(x.sweep.begin(), x.sweep.end(),
                   [](const SweepAxis& a, const SweepAxis& b) { return a.line < b.line; });
}

// [sampling]: method, samples, seed and the sampled parameters in file order.
void parse_sampling_table(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table* s = r.table(root, "sampling", false);
  if (s == nullptr) return;
  r.only_keys("sampling", *s, {"method", "samples", "seed", "parameters"});
  Sampling sampling;
  sampling.seed = x.seed;
  if (const toml::node* n = s->get("method")) {
    const std::string m = r.string("sampling.method", *n);
    if (m == "random") {
      sampling.method = SamplingMethod::kRandom;
    } else if (m == "lhs" || m == "latin_hypercube") {
      sampling.method = SamplingMethod::kLatinHypercube;
    } else {
      r.fail("sampling.method", *n, "expected \"random\" or \"lhs\"");
    }
  }
  const toml::node* samples = s->get("samples");
  if (samples == nullptr)
    throw ValueError("sampling.samples: missing", r.path(), Reader::line_of(*s));
  sampling.samples = static_cast<std::size_t>(r.integer("sampling.samples", *samples, 1));
  if (const toml::node* n = s->get("seed")) {
    sampling.seed = static_cast<std::uint64_t>(r.integer("sampling.seed", *n, 0));
  }
  const toml::table* params = r.table(*s, "parameters", false);
  if (params == nullptr || params->empty()) {
    throw ValueError("sampling.parameters: missing (name = { uniform = [low, high] }, ...)",
                     r.path(), Reader::line_of(*s));
  }
  for (auto&& [key, node] : *params) {
    const std::string name(key.str());
    claim_parameter(r, x, name, node);
    sampling.parameters.push_back(r.sampled("sampling.parameters." + name, name, node));
  }
  std::stable_sort(
      sampling.parameters.begin(), sampling.parameters.end(),
      [](const SampledParameter& a, const SampledParameter& b) { return a.line < b.line; });
  x.sampling = std::move(sampling);
}

// outputs.metrics: names from the metric catalogue.
void parse_metrics(const Reader& r, const toml::node& node, Experiment& x) {
  for (const toml::node& m : r.array("outputs.metrics", node, 0)) {
    const std::string name = r.string("outputs.metrics", m);
    if (find_metric(name) == nullptr) {
      std::string list;
      for (const MetricInfo& info : metric_catalog()) {
        list += (list.empty() ? "" : ", ") + std::string(info.name);
      }
      r.fail("outputs.metrics", m, "unknown metric '" + name + "' (known: " + list + ")");
    }
    x.metrics.push_back(name);
  }
}

// outputs.keep: the kinds of per-run files, each once.
void parse_keep(const Reader& r, const toml::node& node, Experiment& x) {
  x.keep_line = Reader::line_of(node);
  for (const toml::node& k : r.array("outputs.keep", node, 0)) {
    const KeptFile kind = one_of(r, "outputs.keep", k, kKeptFiles, kept_file_name);
    if (std::find(x.keep.begin(), x.keep.end(), kind) != x.keep.end()) {
      r.fail("outputs.keep", k, "'" + std::string(kept_file_name(kind)) + "' given twice");
    }
    x.keep.push_back(kind);
  }
}

// [outputs]: metrics, kept files and how meshes and images are written.
void parse_outputs_table(const Reader& r, const toml::table& root, Experiment& x) {
  if (const toml::table* out = r.table(root, "outputs", false)) {
    r.only_keys("outputs", *out,
                {"metrics", "keep", "reference", "mesh_format", "image_size", "image_view"});
    if (const toml::node* n = out->get("mesh_format")) {
      x.mesh_format = one_of(r, "outputs.mesh_format", *n, kKeptMeshFormats, mesh_format_name);
    }
    if (const toml::node* n = out->get("image_view")) {
      x.image_view = one_of(r, "outputs.image_view", *n, kViews, view_name);
    }
    if (const toml::node* n = out->get("image_size")) {
      const std::optional<ImageSize> size = find_image_size(r.string("outputs.image_size", *n));
      if (!size) {
        r.fail("outputs.image_size", *n,
               "expected \"WIDTHxHEIGHT\", each 1.." + std::to_string(kMaxImageSide) +
                   ", e.g. \"640x480\"");
      }
      x.image_width = size->width;
      x.image_height = size->height;
    }
    if (const toml::node* n = out->get("reference")) {
      x.reference_file = r.resolve("outputs.reference", *n);
    }
    if (const toml::node* n = out->get("metrics")) parse_metrics(r, *n, x);
    if (const toml::node* n = out->get("keep")) parse_keep(r, *n, x);
  }
  if (x.metrics.empty()) {
    for (const MetricInfo& info : metric_catalog()) {
      if (info.by_default) x.metrics.emplace_back(info.name);
    }
  }
}

// [runner]: limits of one run.
void parse_runner_table(const Reader& r, const toml::table& root, Experiment& x) {
  const toml::table* runner = r.table(root, "runner", false);
  if (runner == nullptr) return;
  r.only_keys("runner", *runner, {"time_limit_s"});
  if (const toml::node* n = runner->get("time_limit_s")) {
    const double limit = r.number("runner.time_limit_s", *n);
    if (limit <= 0.0) r.fail("runner.time_limit_s", *n, "must be positive");
    x.time_limit_s = limit;
  }
}

constexpr std::string_view kReplicatesMarker = "\n# replicates overridden: ";

// The text a result database stores after override_replicates ends in its marker; reading it
// back gives the replicates the runs had.
void apply_replicates_marker(std::string_view toml_text, Experiment& x) {
  const auto at = toml_text.rfind(kReplicatesMarker);
  if (at == std::string_view::npos) return;
  std::size_t replicates = 0;
  const std::string_view digits = toml_text.substr(at + kReplicatesMarker.size());
  const auto [end, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), replicates);
  if (error == std::errc() && replicates > 0 &&
      std::string_view(end, digits.data() + digits.size()) == "\n") {
    x.replicates = replicates;
  }
}
}  // namespace

std::vector<std::string> Experiment::swept_names() const {
  std::vector<std::string> names;
  for (const SweepAxis& a : sweep) names.push_back(a.name);
  if (sampling) {
    for (const SampledParameter& p : sampling->parameters) names.push_back(p.name);
  }
  return names;
}

std::size_t Experiment::grid_points() const {
  std::size_t n = 1;
  for (const SweepAxis& a : sweep) n *= a.values.size();
  return n;
}

std::size_t Experiment::points() const {
  return grid_points() * (sampling ? sampling->samples : 1);
}

std::size_t Experiment::runs() const { return points() * replicates; }

Experiment parse_experiment(std::string_view toml_text, const std::string& path) {
  const toml::table root = parse_toml_text(toml_text, path);
  const Reader r(path);
  Experiment x;
  x.path = path;
  x.text = std::string(toml_text);
  r.only_keys("", root,
              {"experiment", "model", "parameters", "sweep", "sampling", "outputs", "runner",
               "distance", "comparison", "ttest", "table", "report"});
  parse_experiment_table(r, root, x);
  parse_model_table(r, root, x);
  parse_fixed_parameters(r, root, x);
  parse_sweep_table(r, root, x);
  parse_sampling_table(r, root, x);
  // Counted in doubles: a product of axis sizes can overflow std::size_t.
  double runs = static_cast<double>(x.replicates);
  for (const SweepAxis& a : x.sweep) runs *= static_cast<double>(a.values.size());
  if (x.sampling) runs *= static_cast<double>(x.sampling->samples);
  check_run_count(runs, "", path);
  parse_outputs_table(r, root, x);
  parse_comparisons(r, root, x);
  parse_runner_table(r, root, x);
  apply_replicates_marker(toml_text, x);
  return x;
}

void override_replicates(Experiment& x, std::size_t replicates) {
  if (replicates == 0) throw ValueError("replicates must be at least 1");
  check_run_count(static_cast<double>(x.points()) * static_cast<double>(replicates),
                  "--replicates " + std::to_string(replicates) + ": ", x.path);
  x.replicates = replicates;
  x.text += std::string(kReplicatesMarker) + std::to_string(replicates) + "\n";
}

Experiment read_experiment(const std::string& path) {
  return parse_experiment(read_text_input_file(path), path);
}

}  // namespace fspm::experiments
