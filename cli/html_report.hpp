#pragma once
// The HTML report of `fspm report --html` (docs/experiments.md): DIR/report/index.html with
// everything it needs beside it, so it opens from file:// without a network: the browser
// libraries (cli/report_web_assets.hpp), data.js with the Markdown report and every run
// (cli/html_report_data.hpp), and the trees as .glb (cli/html_report_trees.hpp). The page
// (report_web/src/report.js) shows the Markdown report's sections and tables, and fills the
// placeholders below with interactive plots and 3D views.
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/results_db.hpp"

namespace fspm::cli {

// The section "Metrics against the swept parameters" with its explanation and the placeholder
// the page fills with one plot per metric and swept parameter; empty when no parameter has two
// values.
std::string html_sweeps_markdown(const experiments::ExperimentInfo& info,
                                 const std::vector<experiments::RunRecord>& runs);

// The comparisons' box plots: explanation and placeholder.
std::string html_comparisons_markdown();

struct HtmlReportInput {
  const experiments::Experiment* experiment = nullptr;  // null: tables only
  const experiments::ExperimentInfo* info = nullptr;
  const std::vector<experiments::RunRecord>* runs = nullptr;
  const experiments::ComparisonResults* comparisons = nullptr;  // null: none computed
  std::string markdown;  // the report, with the placeholders above instead of figures
  std::string dir;       // the experiment's output directory
};

// Writes DIR/report/ (every file atomically) and returns the path of its index.html. Adds the
// selected trees and, for comparisons, a pair per comparison side by side to the report. Throws
// IoError when the browser files are missing or a file cannot be written.
std::filesystem::path write_html_report(const HtmlReportInput& input);

}  // namespace fspm::cli
