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

}  // namespace
}  // namespace fspm::experiments
