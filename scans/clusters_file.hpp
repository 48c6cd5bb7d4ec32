#pragma once
// The .clusters file: a compact little-endian binary form of a ClusterModel (layout in
// docs/formats.md). Skeleton positions and radii are 32-bit floats (relative to a double origin in
// version 3); hull vertices are 16-bit
// integers inside the hull's bounding box (error below 1/65535 of the box side). Writing is atomic.
#include <string>
#include <string_view>

#include "scans/cluster_model.hpp"

namespace fspm::scans {

inline constexpr std::string_view kClustersMagic = "FSPMCLU2";
// Version 3: version 2 with an origin (3 doubles) after the magic, all positions relative to it;
// written when the root lies beyond kClustersOriginAfterM of zero (projected coordinates, where
// a float would keep only decimetres).
inline constexpr std::string_view kClustersMagicV3 = "FSPMCLU3";
inline constexpr double kClustersOriginAfterM = 1000.0;
// Version 1 (no branch length per cluster) is still read.
inline constexpr std::string_view kClustersMagicV1 = "FSPMCLU1";

// Throws ValueError for a model the format cannot hold (more than 65535 vertices or triangles in
// one hull, a species name over 255 bytes, an empty skeleton), IoError when writing fails.
void write_clusters_file(const ClusterModel& model, const std::string& path);
std::string clusters_bytes(const ClusterModel& model);

// Throws ParseError naming the file and the byte offset of what is wrong.
ClusterModel read_clusters_file(const std::string& path);
ClusterModel parse_clusters_bytes(std::string_view data, const std::string& path);

}  // namespace fspm::scans
