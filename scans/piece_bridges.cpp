#include "scans/piece_bridges.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>
#include <memory>
#include <optional>

#include "scans/disjoint_sets.hpp"

namespace fspm::scans {
namespace {

struct Candidate {
  double length_m = 0.0;
  bool admissible = true;
  std::uint32_t a = 0, b = 0;  // parts: the pieces, then the root piece
  Bridge bridge;               // from in part a, to in part b
};

double length_m(const PointSet& ps, const Bridge& b) {
  return (ps.points[b.from] - ps.points[b.to]).norm();
}

// The pieces and the root piece as parts 0 .. n - 1 and n, each with a k-d tree (the pieces'
// built when first searched) and whether it has an axis (the root piece is the trunk: none).
class Parts {
 public:
  Parts(const PointSet& ps, const std::vector<std::vector<std::uint32_t>>& pieces,
        const PointKdTree& root_index, const std::vector<std::uint32_t>& root_points)
      : ps_(ps),
        pieces_(pieces),
        root_index_(root_index),
        root_points_(root_points),
        adaptors_(pieces.size()),
        trees_(pieces.size()),
        axis_(pieces.size()) {
    for (std::size_t p = 0; p < pieces.size(); ++p) axis_[p] = piece_is_elongated(ps, pieces[p]);
  }
  std::size_t root() const { return pieces_.size(); }
  const std::vector<std::uint32_t>& points(std::size_t p) const {
    return p == root() ? root_points_ : pieces_[p];
  }
  bool axis(std::size_t p) const { return p != root() && axis_[p]; }
  const PointKdTree& tree(std::size_t p) {
    if (p == root()) return root_index_;
    if (!trees_[p]) {
      adaptors_[p] = PointCloudAdaptor{&ps_.points, &pieces_[p]};
      trees_[p] = std::make_unique<PointKdTree>(3, adaptors_[p],
                                                nanoflann::KDTreeSingleIndexAdaptorParams(16));
      trees_[p]->buildIndex();
    }
    return *trees_[p];
  }

 private:
  const PointSet& ps_;
  const std::vector<std::vector<std::uint32_t>>& pieces_;
  const PointKdTree& root_index_;
  const std::vector<std::uint32_t>& root_points_;
  std::vector<PointCloudAdaptor> adaptors_;  // sized once: the trees keep their addresses
  std::vector<std::unique_ptr<PointKdTree>> trees_;
  std::vector<char> axis_;
};

// The shortest edge from part a to part b: each point of a searched in b's tree.
Bridge shortest_edge(const PointSet& ps, Parts& parts, std::size_t a, std::size_t b) {
  const PointKdTree& index = parts.tree(b);
  const std::vector<std::uint32_t>& to = parts.points(b);
  Bridge best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::uint32_t i : parts.points(a)) {
    std::uint32_t j = 0;
    double d2 = 0.0;
    index.knnSearch(ps.points[i].data(), 1, &j, &d2);
    if (d2 < best_d2) best_d2 = d2, best = {i, to[j]};
  }
  return best;
}

// The admissible bridge between parts a and b whose shortest edge is `shortest` (from in a):
// the shortest edge within the gap length, else the shorter of the bridges along the axis of a
// or of b; without one, the shortest edge, admissible only when neither part has an axis.
Candidate weigh(const PointSet& ps, Parts& parts, std::uint32_t a, std::uint32_t b,
                const Bridge& shortest, double gap_m) {
  Candidate c{length_m(ps, shortest), true, a, b, shortest};
  if (c.length_m <= gap_m) return c;
  std::optional<Bridge> best;
  double best_m = std::numeric_limits<double>::infinity();
  if (parts.axis(a)) {
    best = axis_bridge(ps, parts.points(a), parts.tree(b), parts.points(b), shortest);
    if (best) best_m = length_m(ps, *best);
  }
  if (parts.axis(b)) {
    const std::optional<Bridge> from_b = axis_bridge(ps, parts.points(b), parts.tree(a),
                                                     parts.points(a), {shortest.to, shortest.from});
    if (from_b && length_m(ps, *from_b) < best_m) {
      best = Bridge{from_b->to, from_b->from}, best_m = length_m(ps, *from_b);
    }
  }
  if (best) return {best_m, true, a, b, *best};
  c.admissible = !parts.axis(a) && !parts.axis(b);
  return c;
}

// Bridges between pairs of pieces that can be in the spanning tree: a bridge longer than both
// pieces' shortest edges to the root piece closes a cycle whose other bridges are shorter.
void pair_candidates(const PointSet& ps, Parts& parts, const std::vector<double>& to_root_m,
                     double gap_m, std::vector<Candidate>& out) {
  const std::size_t n = parts.root();
  std::vector<Eigen::AlignedBox3d> box(n);
  for (std::size_t p = 0; p < n; ++p) {
    for (std::uint32_t i : parts.points(p)) box[p].extend(ps.points[i]);
  }
  for (std::uint32_t p = 0; p < n; ++p) {
    for (std::uint32_t q = p + 1; q < n; ++q) {
      const double bound_m = std::max(to_root_m[p], to_root_m[q]);
      if (box[p].exteriorDistance(box[q]) > bound_m) continue;
      // The smaller piece searched in the larger one's tree.
      const bool p_smaller = parts.points(p).size() <= parts.points(q).size();
      Bridge s = p_smaller ? shortest_edge(ps, parts, p, q) : shortest_edge(ps, parts, q, p);
      if (!p_smaller) s = {s.to, s.from};
      if (length_m(ps, s) > bound_m) continue;
      out.push_back(weigh(ps, parts, p, q, s, gap_m));
    }
  }
}

}  // namespace

std::vector<Bridge> join_pieces(const PointSet& ps,
                                const std::vector<std::vector<std::uint32_t>>& pieces,
                                const PointKdTree& root_index,
                                const std::vector<std::uint32_t>& root_points,
                                const std::vector<Bridge>& to_root, double gap_m) {
  Parts parts(ps, pieces, root_index, root_points);
  const auto root = static_cast<std::uint32_t>(parts.root());
  std::vector<Candidate> candidates;
  std::vector<double> to_root_m(pieces.size());
  for (std::uint32_t p = 0; p < pieces.size(); ++p) {
    candidates.push_back(weigh(ps, parts, p, root, to_root[p], gap_m));
    to_root_m[p] = length_m(ps, to_root[p]);
  }
  pair_candidates(ps, parts, to_root_m, gap_m, candidates);
  // Kruskal: admissible bridges first, each kind shortest first.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    if (x.admissible != y.admissible) return x.admissible;
    return x.length_m < y.length_m;
  });
  DisjointSets sets(pieces.size() + 1);
  std::vector<Bridge> out;
  for (const Candidate& c : candidates) {
    if (sets.find(c.a) == sets.find(c.b)) continue;
    sets.join(c.a, c.b);
    out.push_back(c.bridge);
  }
  return out;
}

}  // namespace fspm::scans
