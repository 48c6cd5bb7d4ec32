// Tree crowns from one photograph (Argudo ch. 4): the base mesh (inflation system, Argudo 4.3.2)
// from a disc mask filling 48 % of a 256 x 256 image, and the whole reconstruction of the
// example picture (examples/crown/tree_front.png, 256 x 256: mask, inflation, relief, texture
// synthesis, cubemaps), and photographs of 1 000 to 4 000 pixels a side (a synthetic tree,
// bench/synthetic_photograph.hpp) from the automatic mask to the crown and its cubemaps, as
// `fspm crown` does them without reading and writing. Argudo Table 7.1: 2-3 s for the base mesh,
// 40-45 min for the texture synthesis. Goals: base mesh under 0.2 s, whole pipeline under 30 s,
// a 4 000 x 3 000 photograph under 30 s and 2 GB on one core.
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <random>
#include <string>

#include "bench/synthetic_photograph.hpp"
#include "crown/auto_mask.hpp"
#include "crown/base_mesh.hpp"
#include "crown/crown_from_photo.hpp"
#include "crown/gap_fill.hpp"
#include "crown/image_io.hpp"
#include "crown/inflation.hpp"

namespace {

fspm::crown::Mask disc_mask(int size) {
  fspm::crown::Mask m(size, size);
  const double c = 0.5 * (size - 1), r = 0.39 * size;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) m.set(x, y, (x - c) * (x - c) + (y - c) * (y - c) <= r * r);
  }
  return m;
}

void BM_Inflate(benchmark::State& state) {
  const fspm::crown::Mask mask = disc_mask(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const auto sheet = fspm::crown::inflate(mask, {});
    benchmark::DoNotOptimize(fspm::crown::mirrored_mesh(sheet));
  }
  state.counters["crown_pixels"] = static_cast<double>(mask.count());
}
BENCHMARK(BM_Inflate)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

void BM_WholePipeline(benchmark::State& state) {
  const fspm::crown::Raster photo =
      fspm::crown::read_rgb(std::string(FSPM_SOURCE_DIR) + "/examples/crown/tree_front.png");
  for (auto _ : state) {
    const fspm::crown::Mask mask = fspm::crown::auto_mask(photo, {});
    const fspm::crown::Raster texture =
        fspm::crown::fill_gaps(photo, mask, fspm::crown::foreground(photo, 0.12f));
    std::mt19937_64 rng(1);
    benchmark::DoNotOptimize(fspm::crown::reconstruct_crown(texture, mask, {}, rng));
  }
}
BENCHMARK(BM_WholePipeline)->Unit(benchmark::kMillisecond);

// One core, as the command runs: the automatic mask and the foliage at full resolution, the rest
// at the working resolution (docs/crown.md, "Resolution").
void BM_CrownFromPhotograph(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const fspm::crown::Raster photo = fspm::bench::synthetic_photograph(side, side);
  int factor = 0;
  std::size_t vertices = 0;
  for (auto _ : state) {
    const fspm::crown::Mask mask = fspm::crown::auto_mask(photo, {});
    const fspm::crown::Mask foliage = fspm::crown::foreground(photo, 0.12f);
    std::mt19937_64 rng(1);
    const auto model = fspm::crown::reconstruct_crown(photo, mask, {}, rng, &foliage);
    factor = model.working_factor;
    vertices = model.mesh.vertex_count();
    benchmark::DoNotOptimize(model);
  }
  state.counters["working_factor"] = factor;
  state.counters["vertices"] = static_cast<double>(vertices);
  // The process's peak so far: the largest photograph's, as the sizes run in increasing order.
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  state.counters["peak_rss_mb"] = static_cast<double>(usage.ru_maxrss) / 1024.0;
}
BENCHMARK(BM_CrownFromPhotograph)
    ->Arg(1000)
    ->Arg(2000)
    ->Arg(4000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->Repetitions(2);

}  // namespace
