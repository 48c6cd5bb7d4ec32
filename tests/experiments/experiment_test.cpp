#include "experiments/experiment.hpp"

#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

using testing::scratch;
using testing::write;

std::vector<double> numbers(const SweepAxis& axis) {
  std::vector<double> out;
  for (const ParameterValue& v : axis.values) out.push_back(parameter_number(v, axis.name));
  return out;
}

// An experiment file like the branching example of docs/experiments.md.
constexpr const char* kBranchingExample = R"(
[experiment]
name = "branching"
seed = 42
replicates = 2
[model]
kind = "lsystem"                  # lsystem | greenlab | grow | adapt | stages
file = "plant.l"                  # relative to the experiment file
[sweep]                           # the grid is the product of all entries
steps = [6, 7, 8]                 # derivation steps
"define.R" = { linspace = [1.3, 1.6, 4] }   # overrides a #define of the L-system
[outputs]
metrics = ["internodes", "leaves", "height", "total_length"]
)";

TEST(Experiment, BranchingExampleGivesTheProductGrid) {
  const auto dir = scratch("branching");
  write(dir / "plant.l", testing::kLineLSystem);
  const std::string path = write(dir / "exp.toml", kBranchingExample);
  const Experiment x = read_experiment(path);
  EXPECT_EQ(x.name, "branching");
  EXPECT_EQ(x.seed, 42u);
  EXPECT_EQ(x.replicates, 2u);
  EXPECT_EQ(x.model_kind, ModelKind::kLSystem);
  EXPECT_EQ(x.model_file, (dir / "plant.l").string());
  ASSERT_EQ(x.sweep.size(), 2u);
  EXPECT_EQ(x.sweep[0].name, "steps");  // file order, not key order
  EXPECT_EQ(x.sweep[1].name, "define.R");
  EXPECT_EQ(numbers(x.sweep[0]), (std::vector<double>{6, 7, 8}));
  const std::vector<double> r = numbers(x.sweep[1]);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_DOUBLE_EQ(r[0], 1.3);
  EXPECT_NEAR(r[1], 1.4, 1e-12);
  EXPECT_NEAR(r[2], 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(r[3], 1.6);
  EXPECT_EQ(x.runs(), 3u * 4u * 2u);
  EXPECT_EQ(x.swept_names(), (std::vector<std::string>{"steps", "define.R"}));
  EXPECT_EQ(x.metrics,
            (std::vector<std::string>{"internodes", "leaves", "height", "total_length"}));
}

Experiment parse(const std::string& body) {
  return parse_experiment("[experiment]\nname = \"t\"\n[model]\nkind = \"synthetic\"\n" + body,
                          "t.toml");
}

TEST(Experiment, RangesLinspaceLogspaceAndLists) {
  const Experiment x = parse(
      "[sweep]\n"
      "\"x.a\" = { range = [0, 10, 3] }\n"
      "\"x.b\" = { range = [0.0, 1.0, 0.25] }\n"
      "\"x.c\" = { logspace = [1, 100, 3] }\n"
      "\"x.d\" = { range = [5, 2, -1] }\n"
      "\"x.e\" = { values = [\"a\", \"b\"] }\n"
      "\"x.f\" = { linspace = [2, 3, 1] }\n");
  ASSERT_EQ(x.sweep.size(), 6u);
  EXPECT_EQ(numbers(x.sweep[0]), (std::vector<double>{0, 3, 6, 9}));
  EXPECT_TRUE(std::holds_alternative<std::int64_t>(x.sweep[0].values[0]));
  EXPECT_EQ(numbers(x.sweep[1]), (std::vector<double>{0, 0.25, 0.5, 0.75}));
  const auto c = numbers(x.sweep[2]);
  EXPECT_DOUBLE_EQ(c[0], 1.0);
  EXPECT_NEAR(c[1], 10.0, 1e-12);
  EXPECT_DOUBLE_EQ(c[2], 100.0);
  EXPECT_EQ(numbers(x.sweep[3]), (std::vector<double>{5, 4, 3}));
  EXPECT_EQ(std::get<std::string>(x.sweep[4].values[1]), "b");
  EXPECT_EQ(numbers(x.sweep[5]), (std::vector<double>{2}));
  EXPECT_EQ(x.runs(), 4u * 4u * 3u * 3u * 2u * 1u);
}

// The error must be a ValueError on the given line whose message names `key`.
template <typename E = ValueError>
void expect_error(const std::string& body, int line, const std::string& key) {
  try {
    parse(body);
    FAIL() << "no error for:\n" << body;
  } catch (const E& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    EXPECT_EQ(e.file(), "t.toml");
  }
}

// A misspelt model kind is refused where the file names it, with the closest kind.
TEST(Experiment, UnknownModelKindNamesTheClosestKind) {
  try {
    parse_experiment("[experiment]\nname = \"x\"\n[model]\nkind = \"grwo\"\n", "t.toml");
    FAIL() << "a misspelt model kind was accepted";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_NE(std::string(e.what()).find("did you mean 'grow'"), std::string::npos) << e.what();
  }
  for (ModelKind kind : kModelKinds) EXPECT_EQ(find_model_kind(model_kind_name(kind)), kind);
  EXPECT_EQ(model_kind_names(), "lsystem, greenlab, grow, adapt, stages or synthetic");
}

TEST(Experiment, BadInputNamesKeyAndLine) {
  // Lines 1-4 are the header written by parse().
  expect_error("colour = 3\n", 5, "colour");
  expect_error("[sweep]\n\"x.a\" = { range = [0, 10, 0] }\n", 6, "step must not be 0");
  expect_error("[sweep]\n\"x.a\" = { range = [10, 0, 1] }\n", 6, "empty range");
  expect_error("[sweep]\n\"x.a\" = { linspace = [0, 1, 0] }\n", 6, "x.a.linspace");
  expect_error("[sweep]\n\"x.a\" = { logspace = [0, 1, 3] }\n", 6, "positive");
  expect_error("[sweep]\n\"x.a\" = []\n", 6, "empty list");
  expect_error("[sweep]\n\"x.a\" = { grid = [1] }\n", 6, "unknown sweep kind");
  expect_error("[parameters]\n\"x.a\" = 1\n[sweep]\n\"x.a\" = [1, 2]\n", 8, "given twice");
  expect_error("[outputs]\nmetrics = [\"height\", \"heigth\"]\n", 6, "heigth");
  expect_error("[outputs]\nkeep = [\"movie\"]\n", 6, "movie");
  expect_error("[runner]\ntime_limit_s = -1\n", 6, "positive");
  expect_error("[sampling]\nsamples = 4\n[sampling.parameters]\n\"x.a\" = { uniform = [2, 1] }\n",
               8, "low must not exceed high");
  expect_error(
      "[sampling]\nsamples = 4\nmethod = \"sobol\"\n[sampling.parameters]\n"
      "\"x.a\" = { uniform = [0, 1] }\n",
      7, "sampling.method");
  expect_error("[model.extra]\n", 5, "model.extra");
  expect_error<ParseError>("[sweep\n", 5, "");
}

TEST(Experiment, MissingModelFileIsReportedWithItsLine) {
  const auto dir = scratch("missing");
  const std::string path = write(dir / "exp.toml",
                                 "[experiment]\nname = \"m\"\n[model]\nkind = \"lsystem\"\n"
                                 "file = \"nowhere.l\"\n");
  try {
    read_experiment(path);
    FAIL();
  } catch (const IoError& e) {
    EXPECT_EQ(e.line(), 5);
    EXPECT_NE(std::string(e.what()).find("nowhere.l"), std::string::npos);
  }
}

TEST(Experiment, DefaultsRecordEveryMetric) {
  const Experiment x = parse("");
  EXPECT_EQ(x.replicates, 1u);
  EXPECT_EQ(x.runs(), 1u);
  EXPECT_FALSE(x.metrics.empty());
  EXPECT_EQ(x.metrics.back(), "run_time");
}

}  // namespace
}  // namespace fspm::experiments
