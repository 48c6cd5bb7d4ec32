#include "scans/voxel_thinning.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "fspm/error.hpp"

namespace fspm::scans {

ThinnedPoints thin_to_voxels(const PointSet& ps, double voxel_m) {
  if (!(voxel_m > 0.0)) throw ValueError("the voxel size must be positive");
  ThinnedPoints out;
  if (ps.points.empty()) return out;
  Eigen::Vector3d lo = ps.points[0], hi = ps.points[0];
  for (const Eigen::Vector3d& p : ps.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  constexpr double kAxisCells = 2097152.0;  // 2^21: three axes in one 64-bit key
  if ((hi - lo).maxCoeff() / voxel_m >= kAxisCells) {
    throw ValueError("the voxel size is too small for the extent of the point set");
  }
  const std::size_t n = ps.points.size();
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Eigen::Vector3d q = (ps.points[i] - lo) / voxel_m;
    keyed[i] = {(static_cast<std::uint64_t>(q.x()) << 42) |
                    (static_cast<std::uint64_t>(q.y()) << 21) | static_cast<std::uint64_t>(q.z()),
                i};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t a = 0; a < n;) {
    std::size_t b = a;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (; b < n && keyed[b].first == keyed[a].first; ++b) sum += ps.points[keyed[b].second];
    out.points.points.push_back(sum / static_cast<double>(b - a));
    out.counts.push_back(static_cast<std::uint32_t>(b - a));
    a = b;
  }
  return out;
}

}  // namespace fspm::scans
