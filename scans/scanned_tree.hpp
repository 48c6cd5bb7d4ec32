#pragma once
// A scanned tree read as a forester reads it, in one call shared by `fspm encode` and Python:
// stray returns left out (scans/isolated_points.hpp), the cloud encoded into a skeleton and leaf
// clusters (Pirk sec. 3.3, scans/encoder.hpp) and measured like a quantitative structure model
// (scans/tree_measurements.hpp), with every warning of the way in the measurements' list: stray
// points removed, occlusion gaps bridged, a root diameter no breast-height circle confirms.
#include <cstddef>
#include <string>

#include "scans/encoder.hpp"
#include "scans/point_set.hpp"
#include "scans/tree_measurements.hpp"

namespace fspm::scans {

struct ScannedTree {
  EncodeResult encoding;
  TreeMeasurements measurements;
  std::size_t isolated_points = 0;  // stray returns left out before encoding
};

// Throws what encode_point_set and measure_tree throw (an empty or degenerate cloud).
ScannedTree encode_and_measure(const PointSet& points, const EncodeOptions& options = {});

// The warning for the occlusion gaps the neighbour graph bridged: how many, and where (the first
// five midpoints, in the input's coordinates).
std::string bridged_gaps_warning(const EncodeResult& encoding);

}  // namespace fspm::scans
