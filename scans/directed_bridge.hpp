#pragma once
// Bridging an occlusion gap along the branch's direction. Where a scan loses a branch behind
// another (an occlusion gap), the neighbour graph leaves the branch's far part as a piece of its
// own, and the shortest edge to the rest of the tree may cross sideways to a neighbouring limb.
// An elongated piece (a branch segment) is instead joined along its own axis: from one of its ends,
// to the nearest point of another part within a cone about the axis, at most kMaxDetour times the
// shortest edge or the piece's own length away. Round or small pieces (a leaf, a tuft of noise)
// have no axis; which bridge joins each piece is chosen in scans/piece_bridges.hpp.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "scans/point_kd_tree.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

struct Bridge {
  std::uint32_t from = 0;  // in the piece
  std::uint32_t to = 0;    // in the part it is joined to
};

inline constexpr double kBridgeConeDeg = 30.0;  // half-angle of the cone about the piece's axis
inline constexpr std::size_t kMinAxisPoints = 10;
inline constexpr double kMinElongation = 3.0;  // of the first to the second principal extent
inline constexpr double kMaxDetour = 3.0;      // of the shortest edge's length

// Whether the piece has an axis: at least kMinAxisPoints points, kMinElongation times longer than
// wide.
bool piece_is_elongated(const PointSet& points, const std::vector<std::uint32_t>& piece);

// The bridge along the piece's axis: from one of its ends to the nearest point of the target
// (`tree_index` over `tree_points`) inside the cone about the axis, at most kMaxDetour times the
// shortest edge or the piece's length away; none when the piece has no axis or the cone is empty.
std::optional<Bridge> axis_bridge(const PointSet& points, const std::vector<std::uint32_t>& piece,
                                  const PointKdTree& tree_index,
                                  const std::vector<std::uint32_t>& tree_points,
                                  const Bridge& shortest);

}  // namespace fspm::scans
