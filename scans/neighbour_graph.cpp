#include "scans/neighbour_graph.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "fspm/error.hpp"
#include "scans/disjoint_sets.hpp"
#include "scans/piece_bridges.hpp"
#include "scans/point_kd_tree.hpp"

namespace fspm::scans {
namespace {

// k nearest neighbours of every point (itself excluded), row-major n x k.
std::vector<std::uint32_t> nearest_neighbours(const PointSet& ps, const PointKdTree& tree, int k) {
  const std::size_t n = ps.points.size();
  const std::size_t kk = static_cast<std::size_t>(k);
  std::vector<std::uint32_t> knn(n * kk);
  std::vector<std::uint32_t> idx(kk + 1);
  std::vector<double> dist(kk + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t found = tree.knnSearch(ps.points[i].data(), kk + 1, idx.data(), dist.data());
    std::size_t out = 0;
    for (std::size_t j = 0; j < found && out < kk; ++j) {
      if (idx[j] != i) knn[i * kk + out++] = idx[j];
    }
    for (; out < kk; ++out) knn[i * kk + out] = static_cast<std::uint32_t>(i);  // self: no edge
  }
  return knn;
}

// Bridges joining every other piece to the piece of `root`. Each piece's shortest edge to the
// root piece: the point whose nearest root-piece point is nearest, searched first among the
// points' 16 nearest neighbours in `all`; only pieces with no hit there search a tree of the root
// piece. When every such edge is within `gap_m`, those edges join the pieces; when one is longer
// (an occlusion gap), the pieces are joined to each other and to the root piece by their
// shortest admissible bridges (scans/piece_bridges.hpp).
std::vector<Bridge> bridges(const PointSet& ps, const PointKdTree& all, DisjointSets& sets,
                            std::uint32_t root, double gap_m) {
  const std::uint32_t root_set = sets.find(root);
  std::vector<std::uint32_t> main;
  std::vector<std::uint32_t> other;
  for (std::uint32_t i = 0; i < ps.points.size(); ++i) {
    (sets.find(i) == root_set ? main : other).push_back(i);
  }
  if (other.empty()) return {};
  using Best = std::pair<double, Bridge>;
  std::vector<Best> best(ps.points.size(), {std::numeric_limits<double>::infinity(), {}});
  constexpr std::size_t kProbe = 16;
  std::uint32_t idx[kProbe];
  double d2[kProbe];
  for (std::uint32_t i : other) {
    const std::size_t found = all.knnSearch(ps.points[i].data(), kProbe, idx, d2);
    for (std::size_t k = 0; k < found; ++k) {
      if (sets.find(idx[k]) != root_set) continue;
      Best& b = best[sets.find(i)];
      if (d2[k] < b.first) b = {d2[k], {i, idx[k]}};
      break;
    }
  }
  std::vector<std::uint32_t> unresolved;
  bool gaps = false;
  for (std::uint32_t i : other) {
    const double d2_best = best[sets.find(i)].first;
    if (!std::isfinite(d2_best)) unresolved.push_back(i);
    gaps = gaps || !(d2_best <= gap_m * gap_m);
  }
  if (!gaps) {
    std::vector<Bridge> out;
    for (const Best& b : best) {
      if (std::isfinite(b.first)) out.push_back(b.second);
    }
    return out;
  }
  PointCloudAdaptor adaptor{&ps.points, &main};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  for (std::uint32_t i : unresolved) {  // whole pieces without a root-piece point near them
    std::uint32_t j = 0;
    double dist = 0.0;
    tree.knnSearch(ps.points[i].data(), 1, &j, &dist);
    Best& b = best[sets.find(i)];
    if (dist < b.first) b = {dist, {i, main[j]}};
  }
  std::vector<std::vector<std::uint32_t>> pieces;
  std::vector<Bridge> to_root;
  std::vector<std::uint32_t> slot(ps.points.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::uint32_t i : other) {
    const std::uint32_t s = sets.find(i);
    if (slot[s] == std::numeric_limits<std::uint32_t>::max()) {
      slot[s] = static_cast<std::uint32_t>(pieces.size());
      pieces.emplace_back();
      to_root.push_back(best[s].second);
    }
    pieces[slot[s]].push_back(i);
  }
  return join_pieces(ps, pieces, tree, main, to_root, gap_m);
}

// The gap length: kGapSpacings times the median distance from a point to its k-th neighbour (the
// longest edges of the graph where the scan is dense).
double gap_length_m(const PointSet& ps, const std::vector<std::uint32_t>& knn, std::size_t k) {
  std::vector<double> d;
  d.reserve(ps.points.size());
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    d.push_back((ps.points[knn[i * k + k - 1]] - ps.points[i]).norm());
  }
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return kGapSpacings * d[d.size() / 2];
}

}  // namespace

NeighbourGraph build_neighbour_graph(const PointSet& ps, int k, double beta, std::uint32_t root) {
  const std::size_t n = ps.points.size();
  if (n == 0) throw ValueError("the point set is empty");
  if (k < 1) throw ValueError("the neighbour count k must be at least 1");
  const std::size_t kk = static_cast<std::size_t>(k);
  PointCloudAdaptor adaptor{&ps.points};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  const std::vector<std::uint32_t> knn = nearest_neighbours(ps, tree, k);
  DisjointSets sets(n);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // one direction each
  edges.reserve(n * kk);
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::size_t a = 0; a < kk; ++a) {
      const std::uint32_t j = knn[i * kk + a];
      if (j == i) continue;
      // Mutual neighbours: keep the pair once, from the smaller index.
      const auto row = knn.begin() + static_cast<std::ptrdiff_t>(j * kk);
      if (j < i && std::find(row, row + static_cast<std::ptrdiff_t>(kk), i) != row + kk) continue;
      edges.emplace_back(i, j);
      sets.join(i, j);
    }
  }
  NeighbourGraph g;
  g.gap_m = gap_length_m(ps, knn, kk);
  for (const Bridge& b : bridges(ps, tree, sets, root, g.gap_m)) {
    edges.emplace_back(b.from, b.to);
    g.bridge_edges.emplace_back(b.from, b.to);
  }
  g.bridges = g.bridge_edges.size();
  g.offset.assign(n + 1, 0);
  for (const auto& [a, b] : edges) ++g.offset[a + 1], ++g.offset[b + 1];
  std::partial_sum(g.offset.begin(), g.offset.end(), g.offset.begin());
  g.target.resize(g.offset[n]);
  g.weight.resize(g.offset[n]);
  std::vector<std::uint32_t> fill(g.offset.begin(), g.offset.end() - 1);
  for (const auto& [a, b] : edges) {
    const float w = static_cast<float>(std::pow((ps.points[a] - ps.points[b]).norm(), beta));
    g.target[fill[a]] = b, g.weight[fill[a]++] = w;
    g.target[fill[b]] = a, g.weight[fill[b]++] = w;
  }
  return g;
}

}  // namespace fspm::scans
