#include "cli/report_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "cli/run_file_writers.hpp"
#include "cli/run_scene_mesh.hpp"
#include "experiments/render_selection.hpp"
#include "experiments/report.hpp"
#include "experiments/report_notes.hpp"
#include "experiments/sweep_summary.hpp"
#include "fspm/error.hpp"
#include "graphics/chart_figure.hpp"
#include "graphics/image.hpp"
#include "graphics/render.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;
namespace ex = fspm::experiments;

// Swept values with more distinct values than this get VTK's own ticks instead of one per value.
constexpr std::size_t kMaxValueTicks = 12;
// Numeric values with longer labels than this get VTK's own ticks too.
constexpr std::size_t kMaxTickLabel = 6;

std::string number_text(double v) {
  std::ostringstream out;
  out.precision(4);
  out << v;
  return out.str();
}

// "metric (unit)" for a chart's axis.
std::string metric_label(const std::string& metric, ex::ModelKind model_kind) {
  const std::string unit = ex::metric_unit(metric, model_kind);
  return unit.empty() ? metric : metric + " (" + unit + ")";
}

// The mean of `metric` over the successful runs with `parameter` = `value` and, when `age` is
// given, age = `age_value`; n = 0 when none.
ex::Moments moments_at(const std::vector<ex::RunRecord>& runs, const std::string& parameter,
                       const std::string& value, const ex::SweptParameter* age,
                       const std::string& age_value, const std::string& metric) {
  ex::Moments m;
  for (const ex::RunRecord& r : runs) {
    if (r.status != ex::RunStatus::kOk) continue;
    const auto it = r.parameters.find(parameter);
    if (it == r.parameters.end() || ex::parameter_text(it->second) != value) continue;
    if (age != nullptr) {
      const auto a = r.parameters.find(age->name);
      if (a == r.parameters.end() || ex::parameter_text(a->second) != age_value) continue;
    }
    const auto v = r.metrics.find(metric);
    if (v != r.metrics.end() && std::isfinite(v->second)) m.add(v->second);
  }
  return m;
}

// The series of one chart: per age (one series each, when `age` is given), else the mean and
// its ± sd band. A text parameter (presets A, B, C) is a category axis: dots, no lines.
std::vector<graphics::ChartSeries> chart_series(const ex::SweptParameter& parameter,
                                                const std::string& metric,
                                                const std::vector<ex::RunRecord>& runs,
                                                const ex::SweptParameter* age,
                                                const std::vector<double>& xs) {
  const bool line = parameter.numeric();
  std::vector<graphics::ChartSeries> series;
  if (age != nullptr) {
    for (const ex::SweptValue& a : age->values) {
      graphics::ChartSeries s{age->name + " = " + a.text, {}, {}, -1, false, true, true, line};
      for (std::size_t i = 0; i < parameter.values.size(); ++i) {
        const ex::Moments m =
            moments_at(runs, parameter.name, parameter.values[i].text, age, a.text, metric);
        if (m.n == 0) continue;
        s.x.push_back(xs[i]);
        s.y.push_back(m.mean);
      }
      if (!s.x.empty()) series.push_back(std::move(s));
    }
    return series;
  }
  graphics::ChartSeries mean{"mean", {}, {}, 0, false, true, false, line};
  graphics::ChartSeries upper{
      "mean + sd, at most the largest", {}, {}, 0, true, false, false, line};
  graphics::ChartSeries lower{
      "mean - sd, at least the smallest", {}, {}, 0, true, false, false, line};
  for (std::size_t i = 0; i < parameter.values.size(); ++i) {
    const auto it = parameter.values[i].metrics.find(metric);
    if (it == parameter.values[i].metrics.end() || it->second.n == 0) continue;
    mean.x.push_back(xs[i]);
    mean.y.push_back(it->second.mean);
    upper.x.push_back(xs[i]);
    upper.y.push_back(it->second.upper_band());
    lower.x.push_back(xs[i]);
    lower.y.push_back(it->second.lower_band());
  }
  return {mean, upper, lower};
}

// The chart of one metric against one swept parameter; false when fewer than two values have
// the metric.
bool sweep_chart(const ex::SweptParameter& parameter, const std::string& metric,
                 const std::vector<ex::RunRecord>& runs, const ex::SweptParameter* age,
                 ex::ModelKind model_kind, const std::string& x_label,
                 const std::string& png_path) {
  graphics::ChartOptions options;
  const bool numeric = parameter.numeric();
  // A tick per value when the values are few and short (a grid's 10, 20, 30), VTK's own ticks
  // for sampled values such as 15.554084...
  bool value_ticks = !numeric || parameter.values.size() <= kMaxValueTicks;
  for (const ex::SweptValue& v : parameter.values) {
    value_ticks = value_ticks && (!numeric || v.text.size() <= kMaxTickLabel);
  }
  std::vector<double> xs;
  for (std::size_t i = 0; i < parameter.values.size(); ++i) {
    const ex::SweptValue& v = parameter.values[i];
    xs.push_back(numeric ? v.number : static_cast<double>(i));
    if (value_ticks) {
      options.x_ticks.push_back(xs.back());
      options.x_tick_labels.push_back(v.text);
    }
  }
  if (&parameter == age) age = nullptr;  // against the age itself: the means over the rest
  std::vector<graphics::ChartSeries> series = chart_series(parameter, metric, runs, age, xs);
  std::size_t longest = 0;
  for (const graphics::ChartSeries& s : series) longest = std::max(longest, s.x.size());
  // Two values at least (regrow_seconds, say, is only recorded for one set).
  if (series.empty() || longest < 2) return false;
  options.title = metric_label(metric, model_kind);
  options.x_label = x_label;
  options.width = 420;
  options.height = 300;
  graphics::write_line_chart(series, options, png_path);
  return true;
}

// "O: 108, G: 108, T: 108": successful runs per value that recorded the metric.
std::string runs_per_value(const ex::SweptParameter& parameter, const std::string& metric) {
  std::string out;
  for (const ex::SweptValue& v : parameter.values) {
    const auto it = v.metrics.find(metric);
    out += (out.empty() ? "" : ", ") + v.text + ": " +
           std::to_string(it == v.metrics.end() ? 0 : it->second.n);
  }
  return out;
}

}  // namespace

std::string sweep_figures(const ex::Experiment& x, const ex::ExperimentInfo& info,
                          const std::vector<ex::RunRecord>& runs, const std::string& dir) {
  const std::vector<ex::SweptParameter> summary = ex::sweep_summary(info, runs);
  const ex::SweptParameter* age = ex::age_parameter(summary);
  std::string md;
  try {
    for (std::size_t p = 0; p < summary.size(); ++p) {
      const ex::SweptParameter& parameter = summary[p];
      if (parameter.values.size() < 2 || info.metrics.empty()) continue;
      fs::create_directories(fs::path(dir) / "figures");
      const std::string counts = runs_per_value(parameter, info.metrics.front());
      std::string row;
      // What the plants did first, then the timings, as in the tables.
      for (const bool timings : {false, true}) {
        std::string charts;
        for (const std::string& metric : info.metrics) {
          if (ex::is_timing_metric(metric) != timings) continue;
          // A metric only some runs record (pruned_nodes: set T) says how many runs it pools.
          const std::string own = runs_per_value(parameter, metric);
          const std::string label =
              own == counts ? parameter.name : parameter.name + " (runs: " + own + ")";
          const std::string file = "figures/sweep-" + std::to_string(p) + "-" + metric + ".png";
          if (!sweep_chart(parameter, metric, runs, age, x.model_kind, label,
                           (fs::path(dir) / file).string())) {
            continue;
          }
          charts += "![" + metric + " against " + label + "](" + file + ")\n";
        }
        if (!charts.empty()) row += (timings && !row.empty() ? "\nTimings:\n\n" : "") + charts;
      }
      if (row.empty()) continue;
      md += "\n### Against `" + parameter.name + "`\n\nSuccessful runs per value (" + counts +
            ").\n\n" + row;
    }
  } catch (const Error& e) {
    return "\nNote: plots against the swept parameters left out: " + std::string(e.what()) + "\n";
  } catch (const fs::filesystem_error& e) {
    return "\nNote: plots against the swept parameters left out: " + std::string(e.what()) + "\n";
  }
  if (md.empty()) return md;
  const std::string pooled =
      age == nullptr
          ? "the mean of each metric over all successful runs with that value, the other "
            "parameters pooled (solid, dots), and the mean ± its sample standard deviation, kept "
            "within the smallest and largest value (dashed)"
          : "the mean of each metric over the successful runs with that value at each `" +
                age->name + "` (one colour per " + age->name +
                ", the legend names them; never pooled across ages), the other parameters "
                "pooled; against `" +
                age->name + "` itself the mean over all runs and ± its standard deviation";
  return "\n## Metrics against the swept parameters\n\nFor each swept parameter and each value: " +
         pooled +
         ". Text values (presets, sets) are categories: dots without lines between them. The "
         "marginal-means tables above give the numbers.\n" +
         md;
}

std::string comparison_figures(const ex::Experiment& x, const ex::ComparisonResults& c,
                               const std::string& dir) {
  std::map<std::string, std::map<std::string, std::vector<double>>> by_group;
  for (const ex::PairDistance& p : c.pairs) {
    by_group[p.group][p.comparison].push_back(p.value(x.distance.tested));
  }
  std::string md =
      "\n### Figures\n\nOne box plot per group: the box spans the middle half of the distances "
      "(first to third quartile) with a line at the median, the whiskers reach the smallest and "
      "largest; n is the number of pairs.\n\n";
  std::size_t index = 0;
  try {
    fs::create_directories(fs::path(dir) / "figures");
    for (const auto& [group, by_comparison] : by_group) {
      std::vector<std::string> names;
      std::vector<std::vector<double>> values;
      for (const ex::ComparisonSpec& spec : x.comparisons) {
        const auto it = by_comparison.find(spec.name);
        if (it == by_comparison.end() || it->second.empty()) continue;
        names.push_back(spec.name + " (n = " + std::to_string(it->second.size()) + ")");
        values.push_back(it->second);
      }
      if (names.empty()) continue;
      const std::string file = "figures/comparisons_" + std::to_string(index++) + ".png";
      graphics::ChartOptions options;
      options.title = group;
      options.y_label = x.distance.tested == ex::DistanceScale::kRaw ? "edit distance"
                                                                     : "normalized edit distance";
      options.width = 640;
      options.height = 420;
      graphics::write_box_plot(names, values, options, (fs::path(dir) / file).string());
      std::string alt = "distances, " + group + ":";
      for (std::size_t i = 0; i < names.size(); ++i) alt += (i == 0 ? " " : ", ") + names[i];
      md += "![" + alt + "](" + file + ")\n";
    }
  } catch (const Error& e) {
    return "\nNote: figures left out: " + std::string(e.what()) + "\n";
  } catch (const fs::filesystem_error& e) {
    return "\nNote: figures left out: " + std::string(e.what()) + "\n";
  }
  return md;
}

namespace {

// The experiment's image size and view in a parallel projection whose height fits a box of
// `extent` with a 6 % margin (as the perspective framing has), with a scale bar.
graphics::RenderOptions one_scale_options(const ex::Experiment& x, const Eigen::Vector3f& extent) {
  graphics::RenderOptions options;
  options.width = x.image_width;
  options.height = x.image_height;
  options.view = x.image_view;
  const double aspect = static_cast<double>(options.width) / options.height;
  options.ortho_height_m =
      1.06 * graphics::ortho_height_to_fit(options.view, Eigen::Vector3f::Zero(), extent, aspect);
  // "1 model unit", "2 model units", "1 m".
  const std::string unit = ex::length_unit(x.model_kind);
  const bool one = graphics::scale_bar_length(options.ortho_height_m) == 1.0;
  options.scale_bar_unit = one && unit == "model units" ? "model unit" : unit;
  return options;
}

// The paragraph above the renders: their scale, and what the grey shapes are.
std::string one_scale_text(const ex::Experiment& x, const graphics::RenderOptions& options) {
  std::string md = "All pictures at one scale, in a parallel projection (" +
                   std::string(view_name(x.image_view)) + " view): the image height spans " +
                   number_text(options.ortho_height_m) + " " + ex::length_unit(x.model_kind) +
                   ", the black bar is " +
                   number_text(graphics::scale_bar_length(options.ortho_height_m)) + " " +
                   options.scale_bar_unit + ".";
  if (x.model_kind == ex::ModelKind::kGrow || x.model_kind == ex::ModelKind::kAdapt) {
    md +=
        " Grey: the obstacles of the scene the tree grew beside or was adapted to, cut to the "
        "region around it (trees grown in the open are drawn alone).";
  }
  return md + "\n\n";
}

}  // namespace

std::string tree_renders(const ex::Experiment& x, const std::vector<ex::RunRecord>& runs,
                         const std::string& dir) {
  const std::vector<ex::RenderChoice> choices = ex::select_renders(x, runs);
  if (choices.empty()) return {};
  std::map<std::size_t, const ex::RunRecord*> by_run;
  for (const ex::RunRecord& r : runs) by_run[r.run] = &r;
  std::string md = "\n## Selected trees\n\n";
  std::vector<std::string> notes;
  try {
    fs::create_directories(fs::path(dir) / "figures");
  } catch (const std::exception& e) {
    return md + "Note: renders left out: " + std::string(e.what()) + "\n";
  }

  // First pass: the size of every picture's content, for one scale that fits the largest.
  struct Drawn {
    const ex::RenderChoice* choice;
    Eigen::Vector3f lo, hi;
    Obstacles obstacles;
  };
  std::vector<Drawn> drawn;
  Eigen::Vector3f extent = Eigen::Vector3f::Zero();
  for (const ex::RenderChoice& c : choices) {
    try {
      Obstacles obstacles = Obstacles::kNone;
      const graphics::TriangleMesh mesh =
          run_scene_mesh(x, *by_run.at(c.run), dir, run_mesh_options(), obstacles);
      drawn.push_back({&c, mesh.bbox_min(), mesh.bbox_max(), obstacles});
      extent = extent.cwiseMax(mesh.bbox_max() - mesh.bbox_min());
    } catch (const Error& e) {
      notes.push_back("not rendered (run " + std::to_string(c.run) + "): " + e.what());
    }
  }
  if (drawn.empty()) return md + ex::notes_markdown(notes);

  graphics::RenderOptions options = one_scale_options(x, extent);
  md += one_scale_text(x, options);
  for (const Drawn& d : drawn) {
    const ex::RenderChoice& c = *d.choice;
    char name[40];
    std::snprintf(name, sizeof name, "figures/run-%07zu.png", c.run);
    try {
      Obstacles obstacles = Obstacles::kNone;
      const graphics::TriangleMesh mesh =
          run_scene_mesh(x, *by_run.at(c.run), dir, run_mesh_options(), obstacles);
      // The same box height from the ground in every picture, so the ground lies on one row.
      const Eigen::Vector3f centre = 0.5f * (d.lo + d.hi);
      Eigen::Vector3f lo(centre.x() - 0.5f * extent.x(), centre.y() - 0.5f * extent.y(), d.lo.z());
      options.frame = Eigen::AlignedBox3f(lo, lo + extent);
      const graphics::Image image = graphics::render_mesh(mesh, options);
      graphics::write_image(image, (fs::path(dir) / name).string());
      const char* besides =
          d.obstacles == Obstacles::kFarAway
              ? "; the scene's obstacles are too far from the tree to be drawn"
          : d.obstacles == Obstacles::kNone && x.model_kind == ex::ModelKind::kGrow
              ? "; grown without obstacles"
              : "";
      md += "![" + c.group + "](" + std::string(name) + ")\n\n*" + c.caption + besides + "*\n\n";
    } catch (const Error& e) {
      notes.push_back("not rendered (run " + std::to_string(c.run) + "): " + e.what());
    }
  }
  return md + ex::notes_markdown(notes);
}

}  // namespace fspm::cli
