// fspm run / results, run as a user would.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include "run_command.hpp"

namespace fspm::testing {
namespace {

namespace fs = std::filesystem;

std::string write_file(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p.string();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(ExperimentCommands, ExampleSweepExportsOneCsvRowPerRun) {
  const fs::path dir = scratch_dir("exp_example");
  const std::string example = std::string(FSPM_SOURCE_DIR) + "/examples/experiments/branching.toml";
  const CommandResult run =
      run_fspm("run " + example + " --jobs 2 --out " + (dir / "out").string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto summary = nlohmann::json::parse(run.out);
  EXPECT_EQ(summary["ran"], 36);
  EXPECT_EQ(summary["ok"], 36);
  const CommandResult csv = run_fspm("results export " + (dir / "out").string() + " --csv");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  const auto lines = lines_of(csv.out);
  ASSERT_EQ(lines.size(), 37u);
  EXPECT_EQ(lines[0],
            "run,seed,status,seconds,steps,define.r2,define.a0,nodes,internodes,leaves,height,"
            "crown_width,crown_depth,total_length,run_time");
  EXPECT_TRUE(fs::exists(dir / "out" / "runs" / "run-0000035.tree"));
  const CommandResult show = run_fspm("results show " + (dir / "out").string());
  EXPECT_EQ(show.exit_code, 0);
  EXPECT_NE(show.out.find("36 ok"), std::string::npos) << show.out;
  const CommandResult report = run_fspm("report " + (dir / "out").string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  std::ifstream md(dir / "out" / "report.md");
  const std::string md_text((std::istreambuf_iterator<char>(md)), {});
  EXPECT_NE(md_text.find("# Experiment branching"), std::string::npos);
  EXPECT_NE(md_text.find("## Marginal means over `define.a0`"), std::string::npos);
  // A second run into the same directory is refused, the database kept.
  const CommandResult again = run_fspm("run " + example + " --out " + (dir / "out").string());
  EXPECT_EQ(again.exit_code, 1);
  EXPECT_NE(again.err.find("--resume"), std::string::npos) << again.err;
}

// The adapt kind's example: a grown tree moved toward a wall. For every c_psi the tree nearest
// the wall bends more, intercepts less light and loses at least as much as the farthest one; far
// from the wall the default c_psi prunes nothing.
TEST(ExperimentCommands, AdaptExampleSweepsTheWallDistance) {
  const fs::path dir = scratch_dir("exp_adapt");
  const std::string example =
      std::string(FSPM_SOURCE_DIR) + "/examples/experiments/wall_distance.toml";
  const CommandResult run =
      run_fspm("run " + example + " --jobs 2 --out " + (dir / "out").string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out)["ok"], 15);
  const CommandResult out = run_fspm("results export " + (dir / "out").string() + " --json");
  ASSERT_EQ(out.exit_code, 0) << out.err;
  const auto rows = nlohmann::json::parse(out.out)["runs"];
  ASSERT_EQ(rows.size(), 15u);
  std::map<std::pair<double, double>, nlohmann::json> at;  // (c_psi, x) -> metrics
  std::set<double> xs, strengths;
  for (const auto& r : rows) {
    const double x = r["parameters"]["tree_x_m"].get<double>();
    const double s = r["parameters"]["pruning_strength"].get<double>();
    at[{s, x}] = r["metrics"];
    xs.insert(x);
    strengths.insert(s);
  }
  ASSERT_EQ(xs.size(), 5u);
  ASSERT_EQ(strengths.size(), 3u);
  const double far = *xs.begin(), near = *xs.rbegin();
  for (const double s : strengths) {
    const auto& f = at[{s, far}];
    const auto& n = at[{s, near}];
    EXPECT_GT(n["tip_displacement"].get<double>(), f["tip_displacement"].get<double>()) << s;
    EXPECT_LT(n["light_interception"].get<double>(), f["light_interception"].get<double>()) << s;
    // At c_psi = 1 the open tree already prunes its self-shaded inner shoots, and the relative
    // thresholds (scaled with the crown's light, eq. 4.12) fall with the light near the wall, so
    // the count need not rise there; up to the default it must.
    if (s <= 0.8) {
      EXPECT_GE(n["pruned_nodes"].get<double>(), f["pruned_nodes"].get<double>()) << s;
    }
  }
  // Near the wall, a stronger c_psi prunes more; the default (0.8) prunes there, not far away.
  const auto pruned_near = [&](double s) {
    return at[std::make_pair(s, near)]["pruned_nodes"].get<double>();
  };
  EXPECT_LT(pruned_near(0.6), pruned_near(0.8));
  EXPECT_LT(pruned_near(0.8), pruned_near(1.0));
  const auto& default_far = at[{0.8, far}];
  EXPECT_EQ(default_far["pruned_nodes"].get<double>(), 0.0);
}

TEST(ExperimentCommands, BadExperimentIsReportedBeforeAnyRun) {
  const fs::path dir = scratch_dir("exp_bad");
  const std::string exp = write_file(dir / "e.toml",
                                     "[experiment]\nname = \"b\"\n[model]\nkind = \"synthetic\"\n"
                                     "[sweep]\nnodes = { range = [5, 1, 1] }\n");
  const CommandResult r = run_fspm("run " + exp + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("e.toml:6"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sweep.nodes.range"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(ExperimentCommands, CorruptDatabaseIsReportedNotOverwritten) {
  const fs::path dir = scratch_dir("exp_corrupt");
  const std::string exp =
      write_file(dir / "e.toml", "[experiment]\nname = \"c\"\n[model]\nkind = \"synthetic\"\n");
  fs::create_directories(dir / "out");
  write_file(dir / "out" / "results.sqlite", "this is not a database at all, not even close....");
  for (const std::string& cmd : {"run " + exp + " --resume --out " + (dir / "out").string(),
                                 "results show " + (dir / "out").string()}) {
    const CommandResult r = run_fspm(cmd);
    EXPECT_EQ(r.exit_code, 1) << cmd;
    EXPECT_NE(r.err.find("corrupt"), std::string::npos) << r.err;
  }
  std::ifstream in(dir / "out" / "results.sqlite");
  std::string content((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(content, "this is not a database at all, not even close....");
}

// `fspm run` in a child process killed with SIGKILL at random moments, resumed every time: the
// final export has every run exactly once.
TEST(ExperimentCommands, KillNineAndResumeGiveEveryRunOnce) {
  const fs::path dir = scratch_dir("exp_kill");
  const std::string exp = write_file(
      dir / "e.toml",
      "[experiment]\nname = \"k\"\nseed = 5\nreplicates = 2\n[model]\nkind = \"synthetic\"\n"
      "[parameters]\nsleep_ms = 10\n[sweep]\nnodes = { range = [1, 151] }\n");
  const std::string out = (dir / "out").string();
  std::mt19937_64 rng(99);
  for (int attempt = 0; attempt < 3; ++attempt) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const int devnull = ::open("/dev/null", O_WRONLY);
      ::dup2(devnull, 1);
      ::dup2(devnull, 2);
      ::execl(FSPM_EXE, FSPM_EXE, "run", exp.c_str(), "--jobs", "2", "--resume", "--out",
              out.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // fspm takes a while to start on a loaded machine: kill at a random moment after its
    // database exists (the first attempt) or right away (later attempts). The sweep needs at
    // least 1.5 s (300 runs of 10 ms on 2 threads), the attempts at most 1.2 s together.
    const auto t0 = std::chrono::steady_clock::now();
    while (attempt == 0 && !fs::exists(dir / "out" / "results.sqlite") &&
           std::chrono::steady_clock::now() - t0 < std::chrono::seconds(20)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(
        std::chrono::milliseconds(std::uniform_int_distribution<int>(0, 400)(rng)));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
  }
  const CommandResult partial = run_fspm("results show " + out + " --json");
  ASSERT_EQ(partial.exit_code, 0) << partial.err;
  const std::size_t before = nlohmann::json::parse(partial.out)["recorded"].get<std::size_t>();
  EXPECT_LT(before, 300u);
  const CommandResult resume = run_fspm("run " + exp + " --jobs 2 --resume --json --out " + out);
  ASSERT_EQ(resume.exit_code, 0) << resume.err;
  EXPECT_EQ(nlohmann::json::parse(resume.out)["ran"].get<std::size_t>(), 300u - before);
  const CommandResult csv = run_fspm("results export " + out + " --csv");
  const auto lines = lines_of(csv.out);
  ASSERT_EQ(lines.size(), 301u);
  std::set<int> runs;
  for (std::size_t i = 1; i < lines.size(); ++i) runs.insert(std::stoi(lines[i]));
  EXPECT_EQ(runs.size(), 300u);
  EXPECT_EQ(*runs.rbegin(), 299);
}

// SIGTERM and SIGINT stop a sweep cleanly with the shell's code of the signal: 128 + its number.
TEST(ExperimentCommands, InterruptExitCodeNamesTheSignal) {
  const fs::path dir = scratch_dir("exp_signal");
  const std::string exp =
      write_file(dir / "e.toml",
                 "[experiment]\nname = \"k\"\n[model]\nkind = \"synthetic\"\n"
                 "[parameters]\nsleep_ms = 20\n[sweep]\nnodes = { range = [1, 2001] }\n");
  for (const auto& [signal, code] : {std::pair{SIGTERM, 143}, std::pair{SIGINT, 130}}) {
    const std::string out = (dir / ("out" + std::to_string(signal))).string();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      const int devnull = ::open("/dev/null", O_WRONLY);
      ::dup2(devnull, 1);
      ::dup2(devnull, 2);
      ::execl(FSPM_EXE, FSPM_EXE, "run", exp.c_str(), "--jobs", "2", "--out", out.c_str(),
              static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // The handler is in place once the database exists (the sweep then needs 20 s).
    const auto t0 = std::chrono::steady_clock::now();
    while (!fs::exists(fs::path(out) / "results.sqlite") &&
           std::chrono::steady_clock::now() - t0 < std::chrono::seconds(60)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ::kill(child, signal);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << "signal " << signal << " killed fspm run";
    EXPECT_EQ(WEXITSTATUS(status), code) << "signal " << signal;
  }
}

// An experiment's name becomes file names in the current folder only, and the printed command
// is quoted for the shell.
TEST(ExperimentCommands, SlurmFilesNamedAfterTheExperimentStayInTheFolder) {
  const fs::path dir = scratch_dir("exp_slurm_name");
  fs::create_directories(dir / "work");
  write_file(dir / "work" / "e.toml",
             "[experiment]\nname = \"../escaped $(touch pwned)\"\n[model]\nkind = "
             "\"synthetic\"\n");
  const CommandResult r =
      run_fspm("run e.toml --emit-slurm", "cd " + (dir / "work").string() + " && ");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "work" / "_._escaped___touch_pwned_.slurm")) << r.out;
  std::size_t outside = 0;
  for (const auto& e : fs::directory_iterator(dir)) outside += e.path().filename() != "work";
  EXPECT_EQ(outside, 0u) << "a file was written outside the current folder";
  EXPECT_NE(r.out.find("submit it with: sbatch '_._escaped___touch_pwned_.slurm'"),
            std::string::npos)
      << r.out;
  std::ifstream in(dir / "work" / "_._escaped___touch_pwned_.slurm");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("#SBATCH --job-name=_._escaped___touch_pwned_\n"), std::string::npos) << text;
  EXPECT_NE(text.find("/_._escaped___touch_pwned_-results'/shard-"), std::string::npos) << text;
}

TEST(ExperimentCommands, SlurmScriptRunsShardsThatMerge) {
  const fs::path dir = scratch_dir("exp_slurm");
  const std::string exp = write_file(
      dir / "e.toml",
      "[experiment]\nname = \"sl\"\n[model]\nkind = \"synthetic\"\n[sweep]\nnodes = [1, 2, 3, "
      "4, 5]\n");
  const std::string script = (dir / "job.slurm").string();
  const CommandResult r = run_fspm("run " + exp + " --emit-slurm --shards 3 --jobs 2 --out " +
                                   (dir / "out").string() + " --slurm-file " + script);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(script);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("#SBATCH --array=0-2"), std::string::npos) << text;
  EXPECT_NE(text.find("#SBATCH --cpus-per-task=2"), std::string::npos);
  EXPECT_NE(text.find("--shard \"$shard\"/3 --resume"), std::string::npos);
  // Run the script's array tasks by hand, as Slurm would, then merge.
  for (int task = 0; task < 3; ++task) {
    const std::string cmd = "env SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " + script;
    ASSERT_EQ(std::system((cmd + " >/dev/null 2>&1").c_str()), 0) << cmd;
  }
  const std::string merged = (dir / "out" / "merged").string();
  const CommandResult m =
      run_fspm("results merge " + merged + " " + (dir / "out").string() + "/shard-0 " +
               (dir / "out").string() + "/shard-1 " + (dir / "out").string() + "/shard-2 --json");
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const auto j = nlohmann::json::parse(m.out);
  EXPECT_EQ(j["rows"], 5);
  EXPECT_EQ(j["missing"], 0);
}

}  // namespace
}  // namespace fspm::testing

namespace fspm::testing {
namespace {

// Two MPI ranks on this machine give the rows of the local runner (timings aside).
// keep = ["mesh", "image"]: a mesh (here PLY) and a PNG of the requested size per run, listed in
// the run's row; the report renders the median tree of the first point at the same size.
TEST(ExperimentCommands, KeptMeshesAndImagesAndReportRenders) {
  const fs::path dir = scratch_dir("exp_keep");
  const std::string exp = write_file(
      dir / "e.toml",
      "[experiment]\nname = \"k\"\nseed = 3\nreplicates = 2\n[model]\nkind = \"lsystem\"\n"
      "file = \"" +
          std::string(FSPM_SOURCE_DIR) +
          "/examples/lsystems/stochastic_plant.l\"\n"
          "[sweep]\nsteps = [2, 3]\n[outputs]\nmetrics = [\"internodes\", \"height\"]\n"
          "keep = [\"mesh\", \"image\"]\nmesh_format = \"ply\"\nimage_size = \"160x120\"\n"
          "[report]\nrenders = 1\n");
  const std::string out = (dir / "out").string();
  const CommandResult run = run_fspm("run " + exp + " --jobs 2 --out " + out);
  if (run.err.find("needs a writer") != std::string::npos ||
      run.err.find("needs an X display") != std::string::npos) {
    GTEST_SKIP() << run.err;  // built without VTK, or no display and no xvfb-run
  }
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // PNG: the signature, then the IHDR chunk with the width and height (big-endian) at 16 and 20.
  auto png_size = [](const std::string& png) {
    if (png.size() < 24 || png.substr(1, 3) != "PNG") return std::pair<long, long>(-1, -1);
    auto be = [&](std::size_t at) {
      long v = 0;
      for (std::size_t i = 0; i < 4; ++i) v = v * 256 + static_cast<unsigned char>(png[at + i]);
      return v;
    };
    return std::pair<long, long>(be(16), be(20));
  };
  const auto all = nlohmann::json::parse(run_fspm("results export " + out + " --json").out);
  ASSERT_EQ(all["runs"].size(), 4u);
  for (const auto& row : all["runs"]) {
    const std::size_t index = row["run"].get<std::size_t>();
    char stem[32];
    std::snprintf(stem, sizeof stem, "runs/run-%07zu", index);
    EXPECT_EQ(row["files"],
              nlohmann::json({std::string(stem) + ".ply", std::string(stem) + ".png"}));
    EXPECT_EQ(read_text(dir / "out" / (std::string(stem) + ".ply")).substr(0, 4), "ply\n");
    EXPECT_EQ(png_size(read_text(dir / "out" / (std::string(stem) + ".png"))),
              std::make_pair(160L, 120L));
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "runs" / "run-0000000.tree"));  // not asked for
  // The report renders one tree (renders = 1: the first point), run again from its seed.
  const CommandResult report = run_fspm("report " + out);
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string md = read_text(dir / "out" / "report.md");
  EXPECT_NE(md.find("## Selected trees"), std::string::npos) << md;
  // The lower median of internodes among the two replicates of steps = 2: run 0 or run 1.
  const std::size_t at = md.find("![steps = 2](figures/run-000000");
  ASSERT_NE(at, std::string::npos) << md;
  const std::string figure = md.substr(md.find('(', at) + 1, 23);
  EXPECT_NE(md.find("steps = 2; internodes = "), std::string::npos) << md;
  EXPECT_EQ(png_size(read_text(dir / "out" / figure)), std::make_pair(160L, 120L)) << figure;
  // --no-figures leaves the renders out.
  fs::remove_all(dir / "out" / "figures");
  ASSERT_EQ(run_fspm("report " + out + " --no-figures").exit_code, 0);
  EXPECT_EQ(read_text(dir / "out" / "report.md").find("## Selected trees"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out" / "figures"));
}

TEST(ExperimentCommands, MpiRanksGiveTheLocalResults) {
  if (std::system("command -v mpirun >/dev/null 2>&1") != 0) GTEST_SKIP() << "no mpirun";
  const fs::path dir = scratch_dir("exp_mpi");
  const std::string exp = write_file(
      dir / "e.toml",
      "[experiment]\nname = \"m\"\nseed = 3\nreplicates = 3\n[model]\nkind = \"lsystem\"\n"
      "file = \"" +
          std::string(FSPM_SOURCE_DIR) +
          "/examples/lsystems/stochastic_plant.l\"\n"
          "[sweep]\nsteps = [2, 3, 4]\n[outputs]\nmetrics = [\"internodes\", \"height\"]\n"
          "keep = [\"mesh\"]\n");
  const std::string mpi_out = (dir / "mpi").string();
  const std::string cmd =
      "env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 mpirun "
      "--oversubscribe -np 2 " +
      std::string(FSPM_EXE) + " run " + exp + " --mpi --out " + mpi_out + " > " +
      (dir / "mpi.log").string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream log(dir / "mpi.log");
  const std::string log_text((std::istreambuf_iterator<char>(log)), {});
  if (log_text.find("built without MPI") != std::string::npos) GTEST_SKIP() << "no MPI build";
  ASSERT_EQ(rc, 0) << log_text;
  ASSERT_EQ(run_fspm("run " + exp + " --out " + (dir / "local").string()).exit_code, 0);
  // Compare everything but the timing columns (seconds is column 4).
  auto rows = [](const std::string& csv) {
    std::vector<std::string> out;
    for (const std::string& line : lines_of(csv)) {
      std::vector<std::string> cells;
      std::stringstream in(line);
      for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
      cells.erase(cells.begin() + 3);
      std::string joined;
      for (const std::string& c : cells) joined += c + ",";
      out.push_back(joined);
    }
    return out;
  };
  const auto mpi_rows = rows(run_fspm("results export " + mpi_out + " --csv").out);
  const auto local_rows =
      rows(run_fspm("results export " + (dir / "local").string() + " --csv").out);
  EXPECT_EQ(mpi_rows.size(), 10u);
  EXPECT_EQ(mpi_rows, local_rows);
  // Every rank wrote the meshes of its own runs.
  for (int i = 0; i < 9; ++i) {
    EXPECT_TRUE(fs::exists(mpi_out + "/runs/run-000000" + std::to_string(i) + ".glb")) << i;
  }
}

}  // namespace
}  // namespace fspm::testing
