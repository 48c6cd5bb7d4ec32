// Whole-process start-up of the command line: `fspm --version` and `fspm tree info` on a small
// tree (goal < 50 ms each), `fspm run --help` and `fspm render --help`, handed to fspm-full
// (goal < 100 ms each), and `fspm-full --version` for comparison.
// Each iteration also starts /bin/true, so the counter vs_true (the command's time over
// /bin/true's in the same run) is comparable across machines and loads.
#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>

#include <string>
#include <vector>
#include "fspm/elapsed.hpp"

extern char** environ;

namespace {

// Seconds from spawning `args` (stdout and stderr to /dev/null) to its exit.
double run_seconds(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  int status = 0;
  if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0) {
    waitpid(pid, &status, 0);
  }
  posix_spawn_file_actions_destroy(&actions);
  return fspm::seconds_since(t0);
}

void measure(benchmark::State& state, const std::vector<std::string>& args) {
  double command = 0.0, peer = 0.0;
  for (auto _ : state) {
    const double s = run_seconds(args);
    state.SetIterationTime(s);
    command += s;
    peer += run_seconds({"/bin/true"});
  }
  state.counters["vs_true"] = peer > 0.0 ? command / peer : 0.0;
}

const std::string kBin = FSPM_BIN_DIR;
const std::string kTree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";

void BM_FspmVersion(benchmark::State& state) { measure(state, {kBin + "/fspm", "--version"}); }
BENCHMARK(BM_FspmVersion)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_FspmTreeInfo(benchmark::State& state) {
  measure(state, {kBin + "/fspm", "tree", "info", kTree});
}
BENCHMARK(BM_FspmTreeInfo)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);

// Handed to fspm-full, which defines every option of the command.
void BM_FspmRunHelp(benchmark::State& state) { measure(state, {kBin + "/fspm", "run", "--help"}); }
BENCHMARK(BM_FspmRunHelp)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_FspmRenderHelp(benchmark::State& state) {
  measure(state, {kBin + "/fspm", "render", "--help"});
}
BENCHMARK(BM_FspmRenderHelp)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);

void BM_FspmFullVersion(benchmark::State& state) {
  measure(state, {kBin + "/fspm-full", "--version"});
}
BENCHMARK(BM_FspmFullVersion)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(1.0);

}  // namespace
