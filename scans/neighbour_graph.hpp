#pragma once
// The neighbour graph of a point set (Pirk sec. 3.3.1, after Livny et al. 2010): every point is
// joined to its k nearest neighbours, and each edge (u, v) weighs |u - v|^beta. Pieces the scan
// left disconnected (occlusion gaps) are bridged to the piece holding the lowest point by the
// shortest edge between them, so the shortest-path tree reaches every point. Where a gap is longer
// than a few point spacings, the pieces are joined to each other first, as a minimum spanning
// tree over pieces whose bridges run along a piece's own axis when it has one
// (scans/piece_bridges.hpp).
#include <cstdint>
#include <utility>
#include <vector>

#include "scans/point_set.hpp"

namespace fspm::scans {

// Symmetric graph in compressed sparse rows: the neighbours of point i are
// target[offset[i] .. offset[i + 1]), with their edge weights.
struct NeighbourGraph {
  std::vector<std::uint32_t> offset;
  std::vector<std::uint32_t> target;
  std::vector<float> weight;
  std::size_t bridges = 0;  // edges added to join disconnected pieces
  std::vector<std::pair<std::uint32_t, std::uint32_t>> bridge_edges;  // (piece, tree) points
  // Bridges longer than this are occlusion gaps: kGapSpacings times the median distance from a
  // point to its k-th neighbour.
  double gap_m = 0.0;
};

inline constexpr double kGapSpacings = 4.0;

// k nearest neighbours (k >= 1) joined both ways, weights |u - v|^beta; `root` is the point the
// other pieces are bridged towards. Throws ValueError when points is empty.
NeighbourGraph build_neighbour_graph(const PointSet& points, int k, double beta,
                                     std::uint32_t root);

}  // namespace fspm::scans
