#include "experiments/run_record.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "experiments/run_execution.hpp"
#include "fspm/error.hpp"

namespace fspm::experiments {
namespace {

RunRecord failed_run() {
  RunRecord r;
  r.run = 7;
  r.point = 3;
  r.replicate = 1;
  r.seed = 12345678901234ULL;
  r.status = RunStatus::kError;
  r.seconds = 0.25;
  r.parameters["years"] = std::int64_t{20};
  r.parameters["alpha"] = 2.5;
  r.parameters["preset"] = std::string("B");
  r.metrics["height"] = std::nan("");
  r.metrics["nodes"] = 42.0;
  r.error = "shadow grid: too large";
  r.files = {"runs/7.tree"};
  r.finished_at = "2026-01-02T03:04:05Z";
  return r;
}

// The row as written by hand: NaN metrics and an empty error are null, parameters keep their
// types.
TEST(RunRecord, JsonHasNullForMissingValues) {
  RunRecord r = failed_run();
  const nlohmann::json j = run_record_json(r);
  EXPECT_TRUE(j.at("metrics").at("height").is_null());
  EXPECT_EQ(j.at("metrics").at("nodes").get<double>(), 42.0);
  EXPECT_EQ(j.at("error").get<std::string>(), "shadow grid: too large");
  EXPECT_EQ(j.at("status").get<std::string>(), "error");
  EXPECT_TRUE(j.at("parameters").at("years").is_number_integer());
  EXPECT_EQ(j.at("parameters").at("preset").get<std::string>(), "B");
  EXPECT_EQ(j.at("seed").get<std::uint64_t>(), 12345678901234ULL);
  r.error.clear();
  EXPECT_TRUE(run_record_json(r).at("error").is_null());
}

// The text the MPI ranks send reads back as the same record, an empty error included.
TEST(RunRecord, TextRoundTripKeepsEveryField) {
  for (const bool with_error : {true, false}) {
    RunRecord r = failed_run();
    if (!with_error) r.error.clear();
    const RunRecord back = record_from_json(record_to_json(r));
    EXPECT_EQ(back.run, r.run);
    EXPECT_EQ(back.point, r.point);
    EXPECT_EQ(back.replicate, r.replicate);
    EXPECT_EQ(back.seed, r.seed);
    EXPECT_EQ(back.status, r.status);
    EXPECT_EQ(back.seconds, r.seconds);
    EXPECT_EQ(back.parameters, r.parameters);
    EXPECT_TRUE(std::isnan(back.metrics.at("height")));
    EXPECT_EQ(back.metrics.at("nodes"), 42.0);
    EXPECT_EQ(back.error, r.error);
    EXPECT_EQ(back.files, r.files);
    EXPECT_EQ(back.finished_at, r.finished_at);
  }
}

}  // namespace
}  // namespace fspm::experiments

namespace fspm::experiments {
namespace {

TEST(RunStatusNames, EveryStatusBothWays) {
  for (RunStatus s : {RunStatus::kOk, RunStatus::kError, RunStatus::kTimeout}) {
    EXPECT_EQ(run_status_from_name(run_status_name(s)), s);
  }
  EXPECT_EQ(run_status_name(RunStatus::kTimeout), "timeout");
  EXPECT_THROW(run_status_from_name("okay"), ValueError);
}

}  // namespace
}  // namespace fspm::experiments
