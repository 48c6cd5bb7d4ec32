// Reading measured plants: the largest file of OpenAlea's MTG test data (test9_noylum2.mtg,
// 747 kB, 8 303 entities at three scales, 22 features) parsed into its multiscale graph, and that
// graph turned into the tree of its finest scale (geometry, units, attributes). Items are
// entities.
#include <benchmark/benchmark.h>

#include "fspm/input_file.hpp"
#include "fspm/mtg_reader.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/warning.hpp"

namespace {

const std::string& noylum_text() {
  static const std::string text = fspm::read_text_input_file(
      std::string(FSPM_SOURCE_DIR) + "/tests/data/mtg/openalea/test9_noylum2.mtg");
  return text;
}

void BM_MtgRead(benchmark::State& state) {
  const std::string& text = noylum_text();
  std::size_t entities = 0;
  for (auto _ : state) {
    const fspm::Mtg g = fspm::read_mtg(text, "noylum2.mtg");
    entities = g.size() - 1;
    benchmark::DoNotOptimize(entities);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * entities));
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
}
BENCHMARK(BM_MtgRead)->Unit(benchmark::kMillisecond);

void BM_MtgToTree(benchmark::State& state) {
  const fspm::Mtg g = fspm::read_mtg(noylum_text(), "noylum2.mtg");
  fspm::MtgTreeOptions o;
  o.length_unit = fspm::LengthUnit::kCentimetre;
  o.diameter_unit = fspm::LengthUnit::kMillimetre;
  for (auto _ : state) benchmark::DoNotOptimize(fspm::mtg_to_tree(g, o).size());
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * (g.size() - 1)));
}
BENCHMARK(BM_MtgToTree)->Unit(benchmark::kMillisecond);

}  // namespace
