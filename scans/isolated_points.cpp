#include "scans/isolated_points.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "scans/point_kd_tree.hpp"

namespace fspm::scans {
namespace {

// The mean distance from each point to its k nearest other points.
std::vector<double> mean_neighbour_distances(const PointSet& ps, int k) {
  PointCloudAdaptor adaptor{&ps.points};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  const auto kk = static_cast<std::size_t>(k) + 1;  // the point itself comes first
  std::vector<std::uint32_t> idx(kk);
  std::vector<double> d2(kk);
  std::vector<double> out(ps.points.size());
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    const std::size_t found = tree.knnSearch(ps.points[i].data(), kk, idx.data(), d2.data());
    double sum = 0.0;
    for (std::size_t j = 1; j < found; ++j) sum += std::sqrt(d2[j]);
    out[i] = found > 1 ? sum / static_cast<double>(found - 1) : 0.0;
  }
  return out;
}

}  // namespace

IsolatedPoints remove_isolated_points(const PointSet& ps, const IsolatedPointsOptions& o) {
  IsolatedPoints out;
  if (ps.points.size() < static_cast<std::size_t>(o.neighbours) + 2) {
    out.kept = ps;
    return out;
  }
  const std::vector<double> mean = mean_neighbour_distances(ps, o.neighbours);
  std::vector<double> sorted = mean;
  const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
  std::nth_element(sorted.begin(), mid, sorted.end());
  out.threshold_m = std::max(o.factor * *mid, o.min_distance_m);
  out.kept.points.reserve(ps.points.size());
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    if (mean[i] > out.threshold_m) {
      ++out.removed;
    } else {
      out.kept.points.push_back(ps.points[i]);
    }
  }
  return out;
}

}  // namespace fspm::scans
