#include "experiments/report.hpp"

#include <gtest/gtest.h>

namespace fspm::experiments {
namespace {

RunRecord record(std::size_t run, std::size_t point, std::int64_t steps, double height,
                 RunStatus status = RunStatus::kOk) {
  RunRecord r;
  r.run = run;
  r.point = point;
  r.status = status;
  r.parameters = {{"steps", steps}};
  r.metrics = {{"height", height}};
  if (status != RunStatus::kOk) r.error = "boom | bang";
  return r;
}

TEST(Report, MeansAndSampleDeviationsPerPoint) {
  ExperimentInfo info;
  info.name = "r";
  info.total_runs = 6;
  info.swept = {"steps"};
  info.metrics = {"height"};
  // Point 0: heights 1, 2, 3 (mean 2, sample sd 1); point 1: 10 and a failed run.
  const std::vector<RunRecord> runs = {record(0, 0, 6, 1.0), record(1, 0, 6, 2.0),
                                       record(2, 0, 6, 3.0), record(3, 1, 7, 10.0),
                                       record(4, 1, 7, 0.0, RunStatus::kError)};
  const std::string md = markdown_report(info, runs);
  EXPECT_NE(md.find("| 6 | 5 | 4 | 1 | 0 | 1 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 0 | 3 | 6 | 2 ± 1 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 1 | 2 | 7 | 10 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| height (m) |"), std::string::npos) << md;  // no model kind: metres
  EXPECT_NE(md.find("| 4 | error | boom \\| bang |"), std::string::npos) << md;
  // An L-system plant measures in its own units.
  info.experiment_text = "[experiment]\nname = \"r\"\n[model]\nkind = \"lsystem\"\n";
  EXPECT_NE(markdown_report(info, runs).find("| height (model units) |"), std::string::npos);
  info.experiment_text = "[model]\nkind = \"grow\"\n";
  EXPECT_NE(markdown_report(info, runs).find("| height (m) |"), std::string::npos);
}

// The canopy light metrics of grown trees get their columns and units in the report's tables.
TEST(Report, CanopyLightMetricsHaveTheirUnits) {
  ExperimentInfo info;
  info.name = "canopy";
  info.total_runs = 1;
  info.metrics = {"sunlit_leaf_area", "shaded_leaf_area", "star", "light_interception_efficiency",
                  "absorbed_par"};
  info.experiment_text = "[model]\nkind = \"grow\"\n";
  RunRecord r;
  r.run = 0;
  r.point = 0;
  r.status = RunStatus::kOk;
  r.metrics = {{"sunlit_leaf_area", 7.5},
               {"shaded_leaf_area", 6.6},
               {"star", 0.25},
               {"light_interception_efficiency", 0.5},
               {"absorbed_par", 306.8}};
  const std::string md = markdown_report(info, {r});
  EXPECT_NE(md.find("| sunlit_leaf_area (m^2) | shaded_leaf_area (m^2) | star (ratio) | "
                    "light_interception_efficiency (ratio) | absorbed_par (mol/day) |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 7.5 | 6.6 | 0.25 | 0.5 | 306.8 |"), std::string::npos) << md;
}

}  // namespace
}  // namespace fspm::experiments
