#pragma once
// The synthetic tree the scan benchmarks scan, encode and decode: an 8 m trunk with 8 main
// branches of 3 m and 4 twigs each (docs/scans.md).
#include "scans/synthetic_tree.hpp"

namespace fspm::bench {

inline scans::SyntheticTreeOptions synthetic_scan_tree() {
  scans::SyntheticTreeOptions t;
  t.trunk_length_m = 8.0;
  t.branch_length_m = 3.0;
  t.branches = 8;
  t.twigs = 4;
  t.root_diameter_m = 0.4;
  return t;
}

}  // namespace fspm::bench
