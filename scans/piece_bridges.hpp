#pragma once
// Joining the pieces a scan's occlusion left apart into one tree. A crown that floats above a
// bare stump (its lower limbs hidden behind the stem or by leaves) falls into many pieces; joined
// each straight to the stump, every piece gets a bridge of metres across the open crown. Instead
// the pieces are joined as a minimum spanning tree over pieces (Boruvka 1926; Kruskal 1956 on the
// same edges): each pair of pieces, and each piece and the root's piece, is weighed by its
// shortest admissible bridge, and bridges are taken shortest first while they join two parts, so
// that neighbouring pieces of a limb join each other before the limb joins the trunk.
//
// A bridge is admissible when it is no longer than the gap length, or when it runs along the
// axis of an elongated piece at either end (scans/directed_bridge.hpp), or when neither piece
// has an axis (a leaf tuft, noise). Other bridges (an elongated piece joined sideways) are taken
// only where no admissible one joins the parts, so that every piece is joined.
#include <cstdint>
#include <vector>

#include "scans/directed_bridge.hpp"
#include "scans/point_kd_tree.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

// `pieces`: the point indices of each piece other than the root's; `root_index`: a k-d tree over
// the root piece's points `root_points`; `to_root[p]`: the shortest edge from piece p (`from`) to
// the root piece (`to`). Returns pieces.size() bridges that join all pieces and the root piece.
std::vector<Bridge> join_pieces(const PointSet& points,
                                const std::vector<std::vector<std::uint32_t>>& pieces,
                                const PointKdTree& root_index,
                                const std::vector<std::uint32_t>& root_points,
                                const std::vector<Bridge>& to_root, double gap_m);

}  // namespace fspm::scans
