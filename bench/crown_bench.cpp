// Tree crowns from one photograph (Argudo ch. 4): the base mesh (inflation system, Argudo 4.3.2)
// from a 256 x 256 disc mask. Argudo Table 7.1: 2-3 s for the base mesh. Goal: under 0.2 s.
#include <benchmark/benchmark.h>

#include "crown/base_mesh.hpp"
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

}  // namespace
