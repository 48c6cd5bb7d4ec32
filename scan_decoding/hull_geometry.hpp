#pragma once
// Rays against the triangulated hull of a leaf cluster (the alpha shape of Pirk sec. 3.3.2):
// where a patch placed at a docking point leaves the cluster, and whether a docking point lies
// inside it. Hulls are closed triangle meshes, possibly non-convex.
#include <Eigen/Core>
#include <vector>

#include "scans/cluster_model.hpp"

namespace fspm::scan_decoding {

// Distances t > 0 at which origin + t direction crosses a hull triangle, ascending
// (Moeller-Trumbore; `direction` need not be unit, t is in its units).
std::vector<double> ray_hull_crossings(const scans::ClusterHull& hull,
                                       const Eigen::Vector3d& origin,
                                       const Eigen::Vector3d& direction);

// Inside by the parity of the crossings of a ray in a fixed direction not parallel to any axis.
bool inside_hull(const scans::ClusterHull& hull, const Eigen::Vector3d& point);

// Mean of the hull's vertices (zero for none).
Eigen::Vector3d hull_centroid(const scans::ClusterHull& hull);

}  // namespace fspm::scan_decoding
