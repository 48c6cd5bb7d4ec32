#pragma once
// Per-run seeds: a function of the experiment seed and the run index only, so a run gets the same
// seed whatever the number of threads, shards or ranks, and on resume.
#include <cstdint>

namespace fspm::experiments {

// SplitMix64 finalizer (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number
// generators"; the constants are those of java.util.SplittableRandom).
constexpr std::uint64_t splitmix64_mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

// The (index + 1)-th output of a SplitMix64 generator seeded with `experiment_seed` (the state
// advances by the golden-ratio increment once per index, then is mixed), keeping its top 63 bits
// so that a seed is a non-negative signed 64-bit integer in SQLite, JSON and Python alike.
constexpr std::uint64_t run_seed(std::uint64_t experiment_seed, std::uint64_t run_index) {
  return splitmix64_mix(experiment_seed + 0x9E3779B97F4A7C15ULL * (run_index + 1)) >> 1;
}

}  // namespace fspm::experiments
