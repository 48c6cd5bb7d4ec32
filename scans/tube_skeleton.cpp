#include "scans/tube_skeleton.hpp"

#include <algorithm>
#include <limits>

#include "fspm/error.hpp"

namespace fspm::scans {
namespace {

// Where a branch's base joins its parent: segment `segment` of the parent's axis at parameter t.
struct Joint {
  std::size_t parent = 0;
  std::size_t segment = 0;
  double t = 0.0;
  double distance_m = std::numeric_limits<double>::infinity();
  bool base_at_front = true;  // which end of the branch is its base
};

// The nearest point to q on polyline c: fills segment, t and distance of `j` when nearer.
void nearest_on_axis(const std::vector<Eigen::Vector3d>& c, const Eigen::Vector3d& q, Joint& j) {
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const Eigen::Vector3d d = c[i + 1] - c[i];
    const double len2 = d.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((q - c[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
    const double dist = (c[i] + t * d - q).norm();
    if (dist < j.distance_m) j.distance_m = dist, j.segment = i, j.t = t;
  }
}

void reverse(RingPolyline& r) {
  std::reverse(r.centres.begin(), r.centres.end());
  std::reverse(r.radii_m.begin(), r.radii_m.end());
}

// A branch modelled from its parent's surface (its base ring beside the parent's axis) forks
// where its axis, continued backwards, comes nearest to the parent's axis: the line from the
// base ring against the direction of its first segment, sampled over three times the base's
// distance from the parent's axis, refines the joint found from the base ring alone.
void refine_fork(const RingPolyline& parent, const RingPolyline& child, Joint& j) {
  const Eigen::Vector3d base = child.centres[0];
  const Eigen::Vector3d back = (child.centres[0] - child.centres[1]).normalized();
  if (j.distance_m < 0.25 * child.radii_m[0] || !back.allFinite()) return;
  const double reach = 3.0 * j.distance_m;
  constexpr int kSteps = 30;
  Joint best = j;
  double best_gap = j.distance_m;
  for (int k = 1; k <= kSteps; ++k) {
    Joint here = j;
    here.distance_m = std::numeric_limits<double>::infinity();
    nearest_on_axis(parent.centres, base + reach * k / kSteps * back, here);
    if (here.distance_m < best_gap) best_gap = here.distance_m, best = here;
  }
  best.distance_m = j.distance_m;  // the join order stays that of the base ring
  j = best;
}

// The thickest branch among those reaching within a tenth of the model's height of its lowest end.
std::size_t trunk_of(const std::vector<RingPolyline>& b) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const RingPolyline& r : b) {
    for (const Eigen::Vector3d& c : r.centres)
      low = std::min(low, c.z()), high = std::max(high, c.z());
  }
  std::size_t best = 0;
  double best_r = -1.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double z = std::min(b[i].centres.front().z(), b[i].centres.back().z());
    const double r = *std::max_element(b[i].radii_m.begin(), b[i].radii_m.end());
    if (z <= low + 0.1 * (high - low) && r > best_r) best_r = r, best = i;
  }
  return best;
}

// Prim's order: the joined branches in the order they join, each with its joint (the trunk's
// unused); `axes` are turned so that each starts at its base.
std::vector<std::size_t> join_branches(std::vector<RingPolyline>& axes, std::vector<Joint>& joint) {
  const std::size_t n = axes.size(), trunk = trunk_of(axes);
  if (axes[trunk].centres.front().z() > axes[trunk].centres.back().z()) reverse(axes[trunk]);
  std::vector<bool> joined(n, false);
  std::vector<std::size_t> order{trunk};
  joined[trunk] = true;
  joint.assign(n, Joint{});
  // Each waiting branch keeps its best joint to the joined ones, updated by the one joined last.
  for (std::size_t newest = trunk; order.size() < n;) {
    for (std::size_t b = 0; b < n; ++b) {
      if (joined[b]) continue;
      for (const bool front : {true, false}) {
        Joint j{newest, 0, 0.0, std::numeric_limits<double>::infinity(), front};
        nearest_on_axis(axes[newest].centres,
                        front ? axes[b].centres.front() : axes[b].centres.back(), j);
        if (j.distance_m < joint[b].distance_m) joint[b] = j;
      }
    }
    std::size_t next = n;
    for (std::size_t b = 0; b < n; ++b) {
      if (!joined[b] && (next == n || joint[b].distance_m < joint[next].distance_m)) next = b;
    }
    if (!joint[next].base_at_front) reverse(axes[next]);
    refine_fork(axes[joint[next].parent], axes[next], joint[next]);
    joined[next] = true;
    order.push_back(next);
    newest = next;
  }
  return order;
}

// Each axis with its children's forks inserted between its rings; fork_index[b] is the index of
// branch b's fork point in its parent's new axis.
void insert_forks(std::vector<RingPolyline>& axes, const std::vector<std::size_t>& order,
                  const std::vector<Joint>& joint, std::vector<std::size_t>& fork_index) {
  fork_index.assign(axes.size(), 0);
  for (std::size_t p = 0; p < axes.size(); ++p) {
    std::vector<std::size_t> kids;
    for (std::size_t k = 1; k < order.size(); ++k) {
      if (joint[order[k]].parent == p) kids.push_back(order[k]);
    }
    std::sort(kids.begin(), kids.end(), [&joint](std::size_t a, std::size_t b) {
      return std::pair(joint[a].segment, joint[a].t) < std::pair(joint[b].segment, joint[b].t);
    });
    const RingPolyline& old = axes[p];
    RingPolyline now;
    std::size_t kid = 0;
    for (std::size_t i = 0; i < old.centres.size(); ++i) {
      now.centres.push_back(old.centres[i]), now.radii_m.push_back(old.radii_m[i]);
      for (; kid < kids.size() && joint[kids[kid]].segment == i; ++kid) {
        const Joint& j = joint[kids[kid]];
        const double len =
            i + 1 < old.centres.size() ? (old.centres[i + 1] - old.centres[i]).norm() : 0.0;
        if (j.t * len > 1e-6 && (1.0 - j.t) * len > 1e-6) {
          now.centres.push_back(old.centres[i] + j.t * (old.centres[i + 1] - old.centres[i]));
          now.radii_m.push_back(old.radii_m[i] + j.t * (old.radii_m[i + 1] - old.radii_m[i]));
        }
        // At a ring (within a micrometre): the fork is that ring.
        fork_index[kids[kid]] =
            (1.0 - j.t) * len <= 1e-6 && j.t > 0.0 ? now.centres.size() : now.centres.size() - 1;
      }
    }
    axes[p] = std::move(now);
  }
}

NodeId add_bone(TreeGraph& t, NodeId parent, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                double radius, std::uint16_t order) {
  NodeData d;
  d.start = a, d.end = b, d.radius = radius, d.order = order;
  return t.add_node(parent, d);
}

}  // namespace

TreeGraph tube_skeleton(const std::vector<RingPolyline>& branches, const std::string& path) {
  if (branches.empty()) throw ValueError("no branch tube in the mesh", path);
  std::vector<RingPolyline> axes = branches;
  std::vector<Joint> joint;
  const std::vector<std::size_t> order = join_branches(axes, joint);
  std::vector<std::size_t> fork_index;
  insert_forks(axes, order, joint, fork_index);
  // node_at[b][k]: the node ending at point k of branch b's axis (the trunk's base has none).
  std::vector<std::vector<NodeId>> node_at(axes.size());
  std::vector<std::uint16_t> branch_order(axes.size(), 0);
  TreeGraph t;
  for (std::size_t b : order) {
    const RingPolyline& a = axes[b];
    node_at[b].assign(a.centres.size(), kNoNode);
    NodeId prev = kNoNode;
    Eigen::Vector3d from = a.centres[0];
    std::size_t k = 1;
    if (b != order[0]) {
      const std::size_t p = joint[b].parent, f = fork_index[b];
      branch_order[b] = static_cast<std::uint16_t>(branch_order[p] + 1);
      prev = node_at[p][f] != kNoNode ? node_at[p][f] : node_at[p][1];
      from = axes[p].centres[f];
      // A base ring away from the parent's axis (a branch modelled from the parent's surface)
      // gets a bone from the fork; one centred on the axis is the fork itself.
      k = (a.centres[0] - from).norm() < 0.25 * a.radii_m[0] ? 1 : 0;
      node_at[b][0] = prev;
    }
    for (; k < a.centres.size(); ++k) {
      const double r = k == 0 ? a.radii_m[0] : 0.5 * (a.radii_m[k - 1] + a.radii_m[k]);
      prev = add_bone(t, prev, from, a.centres[k], r, branch_order[b]);
      node_at[b][k] = prev;
      from = a.centres[k];
    }
  }
  return t;
}

}  // namespace fspm::scans
