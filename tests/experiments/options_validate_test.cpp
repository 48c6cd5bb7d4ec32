// The experiment runner's option structs check themselves the one way: validate() accepts the
// defaults and throws ValueError whose message names the field.
#include <gtest/gtest.h>

#include <string>

#include "experiments/runner.hpp"
#include "experiments/slurm_script.hpp"
#include "fspm/error.hpp"
#include "tests/validate_refusal.hpp"

namespace fspm::experiments {
namespace {

using test_support::refusal;

TEST(ExperimentOptionsValidate, RunnerShardsNameTheField) {
  EXPECT_NO_THROW(RunnerOptions{}.validate());
  RunnerOptions o;
  o.shard_index = 3;
  o.shard_count = 3;
  EXPECT_NE(refusal(o).find("shard_index/shard_count 3/3"), std::string::npos) << refusal(o);
  o.shard_index = 0;
  o.shard_count = 0;
  EXPECT_NE(refusal(o).find("shard_count"), std::string::npos);
}

TEST(ExperimentOptionsValidate, SlurmOptionsNameTheField) {
  EXPECT_NO_THROW(SlurmOptions{}.validate());
  SlurmOptions o;
  o.shards = 0;
  EXPECT_NE(refusal(o).find("shards"), std::string::npos);
  o = SlurmOptions{};
  o.cpus_per_task = 0;
  EXPECT_NE(refusal(o).find("cpus_per_task"), std::string::npos);
  o = SlurmOptions{};
  o.out_dir = "a\"b";
  EXPECT_NE(refusal(o).find("out_dir"), std::string::npos);
  EXPECT_THROW((void)slurm_script(o), ValueError);
}

}  // namespace
}  // namespace fspm::experiments
