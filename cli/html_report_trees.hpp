#pragma once
// The trees of the HTML report (cli/html_report.hpp): the typical trees of
// experiments/render_selection.hpp and, per comparison, the pair at the median distance, each
// written as a binary glTF (.glb, with its nearby obstacles and per-vertex attributes such as age
// and order, meshed lighter than kept meshes) inside a script trees/run-NNNNNNN.js that hands the
// page its bytes gzipped and in base64: pages opened from file:// may load scripts but not fetch
// files.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/results_db.hpp"

namespace fspm::cli {

struct HtmlTrees {
  nlohmann::json trees = nlohmann::json::array();       // [{"run", "group", "caption"}]
  nlohmann::json pair_views = nlohmann::json::array();  // [{"comparison", "group", "run_a", ...}]
  nlohmann::json files = nlohmann::json::object();      // run (as text) -> script stem
  std::vector<std::string> notes;                       // trees that could not be written
};

// Writes the scripts into `report_dir`/trees; `dir` is the experiment's output directory (kept
// tree files). `comparisons` may be null (no pair views).
HtmlTrees write_html_trees(const experiments::Experiment& experiment,
                           const std::vector<experiments::RunRecord>& runs,
                           const experiments::ComparisonResults* comparisons,
                           const std::string& dir, const std::filesystem::path& report_dir);

}  // namespace fspm::cli
