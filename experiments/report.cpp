#include "experiments/report.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <map>
#include <sstream>

#include "experiments/metrics.hpp"
#include "experiments/sweep_summary.hpp"
#include "fspm/number_text.hpp"

namespace fspm::experiments {
namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "-";
  // Four significant digits are plenty in a table; the database keeps the exact values.
  return format_significant(v);
}

std::string cell(const Moments& m) {
  if (m.n == 0) return "-";
  return m.n > 1 ? number(m.mean) + " ± " + number(m.sd()) : number(m.mean);
}

// The model kind of a stored experiment text, nothing when it cannot be read.
std::optional<ModelKind> model_kind_of(const std::string& experiment_text) {
  try {
    const toml::table t = toml::parse(std::string_view(experiment_text));
    return find_model_kind(t["model"]["kind"].value_or(std::string()));
  } catch (const toml::parse_error&) {
    return std::nullopt;
  }
}

// " (unit)" of a metric, nothing for an unknown one.
std::string unit_of(const std::string& metric, std::optional<ModelKind> model_kind) {
  const std::string unit = metric_unit(metric, model_kind);
  return unit.empty() ? unit : " (" + unit + ")";
}

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|')
      out += "\\|";
    else if (c == '\n')
      out += ' ';
    else
      out += c;
  }
  return out;
}

// The recorded metrics that are (timings) or are not (what the plants did) in seconds.
std::vector<std::string> metrics_of_kind(const std::vector<std::string>& metrics, bool timings) {
  std::vector<std::string> out;
  for (const std::string& m : metrics) {
    if (is_timing_metric(m) == timings) out.push_back(m);
  }
  return out;
}

// "| a | b |" header and separator for `leading` columns followed by the metrics with units.
void table_header(std::ostream& md, const std::vector<std::string>& leading,
                  const std::vector<std::string>& metrics, std::optional<ModelKind> kind) {
  md << '|';
  for (const std::string& c : leading) md << ' ' << escape(c) << " |";
  for (const std::string& m : metrics) md << ' ' << m << unit_of(m, kind) << " |";
  md << "\n|";
  for (std::size_t i = 0; i < leading.size() + metrics.size(); ++i) md << "---|";
  md << '\n';
}

// Per point: the swept values and the moments of every metric over successful replicates.
struct Point {
  std::map<std::string, std::string> values;
  std::map<std::string, Moments> metrics;
  std::size_t runs = 0;
};

void point_table(std::ostream& md, const ExperimentInfo& info,
                 const std::map<std::size_t, Point>& points,
                 const std::vector<std::string>& metrics, std::optional<ModelKind> kind) {
  std::vector<std::string> leading = {"point", "runs"};
  leading.insert(leading.end(), info.swept.begin(), info.swept.end());
  table_header(md, leading, metrics, kind);
  for (const auto& [index, p] : points) {
    md << "| " << index << " | " << p.runs << " |";
    for (const std::string& name : info.swept) md << ' ' << escape(p.values.at(name)) << " |";
    for (const std::string& metric : metrics) {
      const auto it = p.metrics.find(metric);
      md << ' ' << (it == p.metrics.end() ? "-" : cell(it->second)) << " |";
    }
    md << '\n';
  }
}

void marginal_table(std::ostream& md, const SweptParameter& parameter,
                    const std::vector<std::string>& metrics, std::optional<ModelKind> kind) {
  table_header(md, {parameter.name}, metrics, kind);
  for (const SweptValue& v : parameter.values) {
    md << "| " << escape(v.text) << " |";
    for (const std::string& metric : metrics) {
      const auto it = v.metrics.find(metric);
      md << ' ' << (it == v.metrics.end() ? "-" : cell(it->second)) << " |";
    }
    md << '\n';
  }
}

}  // namespace

std::string length_unit(std::optional<ModelKind> model_kind) {
  return model_kind == ModelKind::kLSystem ? "model units" : "m";
}

std::string metric_unit(const std::string& metric, std::optional<ModelKind> model_kind) {
  const MetricInfo* info = find_metric(metric);
  if (info == nullptr) return {};
  std::string unit(info->unit);
  if (unit == "length") unit = length_unit(model_kind);
  if (unit == "length^2") unit = length_unit(model_kind) + "^2";
  return unit;
}

namespace {

// Per parameter point: its runs, swept values and the moments of every metric over its
// successful runs.
std::map<std::size_t, Point> point_statistics(const ExperimentInfo& info,
                                              const std::vector<RunRecord>& runs) {
  std::map<std::size_t, Point> points;
  for (const RunRecord& r : runs) {
    Point& p = points[r.point];
    ++p.runs;
    for (const std::string& name : info.swept) {
      const auto it = r.parameters.find(name);
      p.values[name] = it == r.parameters.end() ? "-" : parameter_text(it->second);
    }
    if (r.status != RunStatus::kOk) continue;
    for (const std::string& metric : info.metrics) {
      const auto it = r.metrics.find(metric);
      if (it == r.metrics.end() || !std::isfinite(it->second)) continue;
      p.metrics[metric].add(it->second);
    }
  }
  return points;
}

}  // namespace

std::string markdown_report(const ExperimentInfo& info, const std::vector<RunRecord>& runs,
                            const std::string& introduction) {
  std::ostringstream md;
  std::size_t ok = 0;
  std::size_t error = 0;
  std::size_t timeout = 0;
  for (const RunRecord& r : runs) {
    ok += r.status == RunStatus::kOk;
    error += r.status == RunStatus::kError;
    timeout += r.status == RunStatus::kTimeout;
  }
  md << "# Experiment " << info.name << "\n\n";
  md << introduction;
  md << "Experiment file: `" << info.experiment_path << "`\n\n";
  md << "| runs | recorded | ok | error | timeout | missing |\n|---|---|---|---|---|---|\n";
  md << "| " << info.total_runs << " | " << runs.size() << " | " << ok << " | " << error << " | "
     << timeout << " | " << info.total_runs - std::min(info.total_runs, runs.size()) << " |\n\n";

  const std::map<std::size_t, Point> points = point_statistics(info, runs);

  // What the plants did here; how long the software took in timings_markdown, at the end.
  const std::optional<ModelKind> kind = model_kind_of(info.experiment_text);
  const std::vector<std::string> biological = metrics_of_kind(info.metrics, false);
  if (!biological.empty()) {
    md << "## Metrics per parameter point\n\nMean ± sample standard deviation over the successful "
          "replicates of each point.\n\n";
    point_table(md, info, points, biological, kind);
    const std::vector<SweptParameter> summary = sweep_summary(info, runs);
    const SweptParameter* age = age_parameter(summary);
    for (const SweptParameter& parameter : summary) {
      md << "\n## Marginal means over `" << escape(parameter.name) << "`\n\n";
      if (age == nullptr || &parameter == age) {
        md << "Mean ± sample standard deviation over all successful runs with each value.\n\n";
        marginal_table(md, parameter, biological, kind);
        continue;
      }
      // Per age: the plants grow, so a mean over ages would describe none of them.
      md << "Mean ± sample standard deviation over the successful runs with each value, one "
            "table per `"
         << escape(age->name) << "` (never pooled across ages).\n";
      for (const SweptValue& a : age->values) {
        for (const SweptParameter& at_age :
             sweep_summary(info, runs_with(runs, age->name, a.text))) {
          if (at_age.name != parameter.name) continue;
          md << "\n### At " << escape(age->name) << " = " << escape(a.text) << "\n\n";
          marginal_table(md, at_age, biological, kind);
        }
      }
    }
  }

  if (error + timeout > 0) {
    md << "\n## Failed runs\n\n| run | status | error |\n|---|---|---|\n";
    for (const RunRecord& r : runs) {
      if (r.status == RunStatus::kOk) continue;
      md << "| " << r.run << " | " << run_status_name(r.status) << " | " << escape(r.error)
         << " |\n";
    }
  }
  return md.str();
}

std::string timings_markdown(const ExperimentInfo& info, const std::vector<RunRecord>& runs) {
  const std::vector<std::string> timings = metrics_of_kind(info.metrics, true);
  if (timings.empty()) return {};
  const std::optional<ModelKind> kind = model_kind_of(info.experiment_text);
  std::ostringstream md;
  md << "\n## Timings per parameter point\n\nSeconds of computing time, mean ± sample standard "
        "deviation over the successful replicates of each point.\n\n";
  point_table(md, info, point_statistics(info, runs), timings, kind);
  for (const SweptParameter& parameter : sweep_summary(info, runs)) {
    md << "\n### Timings over `" << escape(parameter.name)
       << "`\n\nMean ± sample standard deviation over all successful runs with each value.\n\n";
    marginal_table(md, parameter, timings, kind);
  }
  return md.str();
}

std::string summary_tables_markdown(const Experiment& experiment,
                                    const std::vector<RunRecord>& runs) {
  std::ostringstream md;
  for (const SummaryTableSpec& table : experiment.tables) {
    md << "\n## " << (table.title.empty() ? std::string("Summary") : escape(table.title)) << "\n\n";
    if (!table.where.empty()) {
      md << "Runs with";
      for (const auto& [name, value] : table.where) {
        md << ' ' << escape(name) << " = " << escape(parameter_text(value));
      }
      md << "; ";
    }
    md << "mean ± sample standard deviation over the successful runs.\n\n|";
    for (const std::string& name : table.by) md << ' ' << escape(name) << " |";
    md << " runs |";
    for (const std::string& metric : table.metrics) {
      md << ' ' << metric << unit_of(metric, experiment.model_kind) << " |";
    }
    md << "\n|";
    for (std::size_t i = 0; i < table.by.size() + table.metrics.size() + 1; ++i) md << "---|";
    md << '\n';
    // Rows in the order of the runs' first appearance, which follows the grid.
    std::vector<std::vector<std::string>> keys;
    std::map<std::vector<std::string>, std::pair<std::size_t, std::map<std::string, Moments>>> rows;
    for (const RunRecord& r : runs) {
      if (r.status != RunStatus::kOk) continue;
      bool match = true;
      for (const auto& [name, value] : table.where) {
        const auto it = r.parameters.find(name);
        match = match && it != r.parameters.end() &&
                parameter_text(it->second) == parameter_text(value);
      }
      if (!match) continue;
      std::vector<std::string> key;
      for (const std::string& name : table.by) {
        const auto it = r.parameters.find(name);
        key.push_back(it == r.parameters.end() ? "-" : parameter_text(it->second));
      }
      auto [it, inserted] = rows.try_emplace(key);
      if (inserted) keys.push_back(key);
      ++it->second.first;
      for (const std::string& metric : table.metrics) {
        const auto m = r.metrics.find(metric);
        if (m != r.metrics.end() && std::isfinite(m->second))
          it->second.second[metric].add(m->second);
      }
    }
    for (const std::vector<std::string>& key : keys) {
      const auto& [count, moments] = rows.at(key);
      md << '|';
      for (const std::string& v : key) md << ' ' << escape(v) << " |";
      md << ' ' << count << " |";
      for (const std::string& metric : table.metrics) {
        const auto it = moments.find(metric);
        md << ' ' << (it == moments.end() ? "-" : cell(it->second)) << " |";
      }
      md << '\n';
    }
  }
  return md.str();
}

}  // namespace fspm::experiments
