// Frames of the real-time viewer (`fspm view`, offscreen under Xvfb with Mesa's software OpenGL
// when there is no display; the command re-runs itself under xvfb-run): the 11 000-tree
// landscape of examples/landscape at 1280 x 720 with per-instance level of detail and impostors,
// against the same view with every plant at full detail, in the same run (Argudo 2014, chapter 6;
// his Table 7.2 is the published anchor), the landscape's shadow cascades against its one shadow
// map, and the 1.38 M-triangle Leeuwenberg plant.
//
// Manual time is the mean of the frames after the first: they reuse the shadow map, as every
// frame does while the shadow casters stay the same. first_frame_ms, the frame that draws it, is
// what a frame costs when the level-of-detail choice changes.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace {

const std::string kBin = FSPM_BIN_DIR;
const std::string kSource = FSPM_SOURCE_DIR;

struct Frames {
  double steady_ms = 0.0, first_ms = 0.0;
  double triangles = 0.0, impostors = 0.0;
};

// Runs `fspm-full view ARGS --frames N --screenshot TMP --json --no-panel` and reads its JSON.
Frames view_frames(const std::string& args, int frames) {
  const std::string shot =
      (std::filesystem::temp_directory_path() / "fspm_viewer_bench.png").string();
  const std::string command = kBin + "/fspm-full view " + args + " --frames " +
                              std::to_string(frames) + " --screenshot " + shot +
                              " --json --no-panel 2>/dev/null";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  char buffer[4096];
  while (pipe && fgets(buffer, sizeof(buffer), pipe.get()) != nullptr) out += buffer;
  std::filesystem::remove(shot);
  Frames f;
  const nlohmann::json j = nlohmann::json::parse(out, nullptr, false);
  if (j.is_discarded() || !j.contains("mean_frame_ms")) return f;
  f.first_ms = j["first_frame_ms"].get<double>();
  const double mean = j["mean_frame_ms"].get<double>();
  f.steady_ms = frames > 1 ? (mean * frames - f.first_ms) / (frames - 1) : mean;
  f.triangles = j["triangles"].get<double>();
  f.impostors = j.value("impostors", 0.0);
  return f;
}

const std::string kLandscape =
    kSource + "/examples/landscape/landscape.json --leaves --size 1280x720";

// Level of detail with impostors against every plant at its finest, one after the other.
void BM_LandscapeViewerLodVsFull(benchmark::State& state) {
  for (auto _ : state) {
    const Frames lod = view_frames(kLandscape + " --lod", 21);
    // Every plant at its finest, without any level of detail.
    const Frames full = view_frames(kLandscape + " --full-detail", 2);
    if (lod.steady_ms <= 0.0 || full.steady_ms <= 0.0) {
      state.SkipWithError("fspm view failed (no OpenGL 3.3 under Xvfb?)");
      return;
    }
    state.SetIterationTime(lod.steady_ms / 1e3);
    state.counters["lod_fps"] = 1e3 / lod.steady_ms;
    state.counters["lod_first_frame_ms"] = lod.first_ms;
    state.counters["lod_triangles"] = lod.triangles;
    state.counters["impostors"] = lod.impostors;
    state.counters["full_ms"] = full.steady_ms;
    state.counters["full_first_frame_ms"] = full.first_ms;
    state.counters["full_triangles"] = full.triangles;
    state.counters["speedup"] = full.steady_ms / lod.steady_ms;
    state.counters["speedup_first_frames"] = full.first_ms / lod.first_ms;
  }
}
BENCHMARK(BM_LandscapeViewerLodVsFull)
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// The landscape from 60 m above its centre, with three shadow cascades against the one map of
// the whole scene, in the same run: what the cascades' maps cost in the frame that draws them
// (the first; a moving camera redraws one cascade a frame) and in the frames that reuse them.
void BM_LandscapeShadowCascades(benchmark::State& state) {
  const std::string close_up = kLandscape + " --lod --distance 60 --pitch-deg 25";
  for (auto _ : state) {
    const Frames one = view_frames(close_up, 11);
    const Frames cascaded = view_frames(close_up + " --shadow-cascades 3", 11);
    if (one.steady_ms <= 0.0 || cascaded.steady_ms <= 0.0) {
      state.SkipWithError("fspm view failed (no OpenGL 3.3 under Xvfb?)");
      return;
    }
    state.SetIterationTime(cascaded.steady_ms / 1e3);
    state.counters["one_map_ms"] = one.steady_ms;
    state.counters["one_map_first_frame_ms"] = one.first_ms;
    state.counters["cascades_first_frame_ms"] = cascaded.first_ms;
    state.counters["three_cascades_drawn_ms"] = cascaded.first_ms - one.first_ms;
    state.counters["triangles"] = cascaded.triangles;
  }
}
BENCHMARK(BM_LandscapeShadowCascades)
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// The Leeuwenberg plant at 9 cycles (1.38 M triangles, instanced), 1280 x 800.
void BM_CompressedPlantViewerFrame(benchmark::State& state) {
  const std::string plant =
      (std::filesystem::temp_directory_path() / "fspm_viewer_bench_leeuwenberg.toml").string();
  {
    std::unique_ptr<FILE, int (*)(FILE*)> in(
        fopen((kSource + "/examples/greenlab/leeuwenberg.toml").c_str(), "r"), fclose);
    std::unique_ptr<FILE, int (*)(FILE*)> out(fopen(plant.c_str(), "w"), fclose);
    char line[4096];
    while (in && out && fgets(line, sizeof(line), in.get()) != nullptr) {
      const std::string text = line;
      fputs(text.rfind("cycles", 0) == 0 ? "cycles = 9\n" : line, out.get());
    }
  }
  for (auto _ : state) {
    const Frames f = view_frames(plant + " --size 1280x800", 11);
    if (f.steady_ms <= 0.0) {
      state.SkipWithError("fspm view failed (no OpenGL 3.3 under Xvfb?)");
      break;
    }
    state.SetIterationTime(f.steady_ms / 1e3);
    state.counters["first_frame_ms"] = f.first_ms;
    state.counters["triangles"] = f.triangles;
  }
  std::filesystem::remove(plant);
}
BENCHMARK(BM_CompressedPlantViewerFrame)
    ->UseManualTime()
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
