#include "cli/html_report.hpp"

#include <nlohmann/json.hpp>
#include <set>

#include "cli/html_report_data.hpp"
#include "cli/html_report_trees.hpp"
#include "cli/report_light_profile.hpp"
#include "cli/report_web_assets.hpp"
#include "experiments/report.hpp"
#include "experiments/report_notes.hpp"
#include "fspm/atomic_file.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;
namespace ex = fspm::experiments;
using nlohmann::json;

std::string html_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// The 3D views' sections: the typical trees, then the pairs; what they show and how to turn them.
std::string trees_markdown(const ex::Experiment& x, const HtmlTrees& trees) {
  std::string md;
  const std::string how =
      "Drag to turn, scroll to zoom, right-drag to move; the menu colours the tree by a "
      "per-vertex attribute (age, order, ...), grey shapes are the obstacles near the tree.";
  if (!trees.trees.empty()) {
    md += "\n## Selected trees\n\nThe typical tree of each group (the run with the median " +
          std::string(x.render.metric.empty() ? "node count" : x.render.metric) +
          "), each view framed to its tree. " + how + "\n\n<div class=\"fspm-trees\"></div>\n";
  }
  if (!trees.pair_views.empty()) {
    md +=
        "\n## Pairs side by side\n\nFor each comparison, the pair of runs at the median "
        "distance over all its groups, with that distance, the two views at one scale. " +
        how + "\n\n<div class=\"fspm-pairs\"></div>\n";
  }
  return md + ex::notes_markdown(trees.notes);
}

// The section "Light in the crown": explanation, the placeholder of the page's plot and the runs'
// groups; only the notes when no tree has leaf clusters.
std::string light_profile_markdown(const LightProfiles& profiles) {
  if (profiles.trees.empty()) return ex::notes_markdown(profiles.notes);
  std::string groups;
  for (const TreeLightProfile& t : profiles.trees)
    groups += "- run " + std::to_string(t.run) + ": " + t.group + "\n";
  return "\n## Light in the crown\n\n" + light_profile_explanation() +
         " Hover a point for its layer's number of clusters.\n\n"
         "<div class=\"fspm-lightprofile\"></div>\n\n" +
         groups + ex::notes_markdown(profiles.notes);
}

const char* const kIndexHtml = R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>@TITLE@</title>
<link rel="stylesheet" href="lib/report.css">
<script src="lib/marked.min.js"></script>
<script src="lib/safe_markdown.js"></script>
<script src="lib/plotly.min.js"></script>
<script src="lib/three.min.js"></script>
<script src="data.js"></script>
<script src="lib/report.js"></script>
</head>
<body>
<main id="report"><noscript>This report needs JavaScript; report.md beside this folder has the
same tables.</noscript></main>
</body>
</html>
)";

}  // namespace

std::string html_sweeps_markdown(const ex::ExperimentInfo& info,
                                 const std::vector<ex::RunRecord>& runs) {
  bool any = false;
  for (const std::string& name : info.swept) {
    std::set<std::string> values;
    for (const ex::RunRecord& r : runs) {
      const auto it = r.parameters.find(name);
      if (r.status == ex::RunStatus::kOk && it != r.parameters.end())
        values.insert(ex::parameter_text(it->second));
    }
    any = any || values.size() >= 2;
  }
  if (!any || info.metrics.empty()) return {};
  return "\n## Metrics against the swept parameters\n\nFor each swept parameter and each metric: "
         "every successful run as a grey point (hover for its run, seed and parameters), and the "
         "mean over the runs with each value (diamonds), per age when the experiment sweeps "
         "`years` or `age` (one colour per age, never pooled across ages), the other "
         "parameters pooled. Text values (presets, sets) are categories: no line joins them. "
         "The marginal-means tables above give the numbers.\n\n<div class=\"fspm-sweeps\"></div>\n";
}

std::string html_comparisons_markdown() {
  return "\n### Figures\n\nOne box plot per group: the box spans the middle half of the "
         "distances (first to third quartile) with a line at the median, the whiskers reach the "
         "smallest and largest distance (as in report.md); every pair is a point (hover for "
         "both runs, their seeds and parameters); n is the number of pairs.\n\n"
         "<div class=\"fspm-boxplots\"></div>\n";
}

fs::path write_html_report(const HtmlReportInput& in) {
  const fs::path report_dir = fs::path(in.dir) / "report";
  copy_report_web(report_dir / "lib");
  std::string markdown = in.markdown;
  json data = {{"title", "Experiment " + in.info->name},
               {"swept", in.info->swept},
               {"runs", html_runs_json(*in.info, *in.runs)},
               {"comparisons", json::array()},
               {"pairs", html_pairs_json(in.comparisons ? *in.comparisons : ex::ComparisonResults{},
                                         in.experiment ? in.experiment->distance.tested
                                                       : ex::DistanceScale::kNormalized)}};
  std::optional<ex::ModelKind> kind;
  if (in.experiment != nullptr) {
    kind = in.experiment->model_kind;
    for (const ex::ComparisonSpec& c : in.experiment->comparisons)
      data["comparisons"].push_back(c.name);
    const HtmlTrees trees =
        write_html_trees(*in.experiment, *in.runs, in.comparisons, in.dir, report_dir);
    markdown += trees_markdown(*in.experiment, trees);
    const LightProfiles profiles = light_profiles(*in.experiment, *in.runs, in.dir);
    markdown += light_profile_markdown(profiles);
    data["light_profiles"] = html_light_profiles_json(profiles);
    data["trees"] = trees.trees;
    data["pair_views"] = trees.pair_views;
    data["tree_files"] = trees.files;
  } else {
    data["trees"] = data["pair_views"] = json::array();
    data["tree_files"] = json::object();
    data["light_profiles"] = json::array();
  }
  data["metrics"] = html_metrics_json(*in.info, kind);
  data["markdown"] = markdown;
  write_file_atomically((report_dir / "data.js").string(), [&](std::ostream& out) {
    out << "window.FSPM_REPORT = " << data.dump() << ";\n";
  });
  std::string page = kIndexHtml;
  page.replace(page.find("@TITLE@"), 7, html_escape("Experiment " + in.info->name));
  const fs::path index = report_dir / "index.html";
  write_file_atomically(index.string(), [&](std::ostream& out) { out << page; });
  return index;
}

}  // namespace fspm::cli
