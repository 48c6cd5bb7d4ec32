#include "scans/directed_bridge.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fspm::scans {
namespace {

struct PieceAxis {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  bool elongated = false;
};

// The principal axis of the piece; elongated when its spread along the axis is kMinElongation
// times that across (square roots of the covariance's eigenvalues).
PieceAxis piece_axis(const PointSet& ps, const std::vector<std::uint32_t>& piece) {
  PieceAxis a;
  if (piece.size() < kMinAxisPoints) return a;
  for (std::uint32_t i : piece) a.centre += ps.points[i];
  a.centre /= static_cast<double>(piece.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::uint32_t i : piece) {
    const Eigen::Vector3d d = ps.points[i] - a.centre;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d l = eig.eigenvalues().cwiseMax(0.0);  // ascending
  a.axis = eig.eigenvectors().col(2);
  a.elongated = l(2) > kMinElongation * kMinElongation * l(1);
  return a;
}

}  // namespace

bool piece_is_elongated(const PointSet& ps, const std::vector<std::uint32_t>& piece) {
  return piece_axis(ps, piece).elongated;
}

std::optional<Bridge> axis_bridge(const PointSet& ps, const std::vector<std::uint32_t>& piece,
                                  const PointKdTree& tree_index,
                                  const std::vector<std::uint32_t>& tree_points,
                                  const Bridge& shortest) {
  const PieceAxis a = piece_axis(ps, piece);
  if (!a.elongated) return std::nullopt;
  const double cos_cone = std::cos(kBridgeConeDeg * std::numbers::pi / 180.0);
  // The piece's two ends along its axis, each looking outwards.
  auto [lo, hi] = std::minmax_element(piece.begin(), piece.end(), [&](auto i, auto j) {
    return (ps.points[i] - a.centre).dot(a.axis) < (ps.points[j] - a.centre).dot(a.axis);
  });
  // A gap up to kMaxDetour times the shortest edge, or up to the piece's own length.
  const double shortest_m = (ps.points[shortest.from] - ps.points[shortest.to]).norm();
  const double radius_m =
      std::max(kMaxDetour * shortest_m, (ps.points[*hi] - ps.points[*lo]).dot(a.axis));
  std::optional<Bridge> best;
  double best_m = std::numeric_limits<double>::infinity();
  std::vector<std::pair<std::uint32_t, double>> hits;
  for (const auto& [end, outwards] : {std::pair{*lo, Eigen::Vector3d(-a.axis)}, {*hi, a.axis}}) {
    const Eigen::Vector3d& p = ps.points[end];
    hits.clear();
    tree_index.radiusSearch(p.data(), radius_m * radius_m, hits,
                            nanoflann::SearchParams(32, 0.0, false));
    for (const auto& h : hits) {
      const Eigen::Vector3d d = ps.points[tree_points[h.first]] - p;
      const double len = d.norm();
      if (len > 0.0 && d.dot(outwards) >= cos_cone * len && len < best_m) {
        best_m = len, best = Bridge{end, tree_points[h.first]};
      }
    }
  }
  return best;
}

}  // namespace fspm::scans
