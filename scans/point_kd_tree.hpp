#pragma once
// A k-d tree over a point set (nanoflann), for nearest-neighbour queries.
#include <nanoflann.hpp>

#include "scans/point_set.hpp"

namespace fspm::scans {

// nanoflann's view of a vector of points, or of a subset of them by index.
struct PointCloudAdaptor {
  const std::vector<Eigen::Vector3d>* points;
  const std::vector<std::uint32_t>* subset = nullptr;  // null: all points
  std::size_t kdtree_get_point_count() const { return subset ? subset->size() : points->size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const {
    return (*points)[subset ? (*subset)[i] : i][static_cast<Eigen::Index>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using PointKdTree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloudAdaptor>,
                                        PointCloudAdaptor, 3, std::uint32_t>;

}  // namespace fspm::scans
