// The constrained edit distance against an independent brute force over all mappings that
// satisfy Pirk's conditions eq. 4.19-4.21, plus symmetry, child-order invariance and hand cases.
#include "fspm/constrained_edit_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <random>
#include <set>

#include "fspm/error.hpp"
#include "fspm/newick_format.hpp"

namespace fspm {
namespace {

TreeGraph tree_from_parents(const std::vector<int>& parents) {
  TreeGraph t;
  for (const int p : parents) t.add_node(p < 0 ? kNoNode : static_cast<NodeId>(p), NodeData{});
  return t;
}

// Random tree: node v hangs under a uniformly chosen earlier node; integer labels 0..9 and
// random length/radius.
TreeGraph random_tree(std::mt19937_64& rng, int n) {
  std::vector<int> parents{-1};
  for (int v = 1; v < n; ++v) parents.push_back(std::uniform_int_distribution<int>(0, v - 1)(rng));
  TreeGraph t = tree_from_parents(parents);
  t.add_attribute("label");
  auto label = t.attribute("label");
  std::uniform_real_distribution<double> u(0.1, 2.0);
  for (NodeId v = 0; v < t.size(); ++v) {
    label[v] = std::uniform_int_distribution<int>(0, 9)(rng);
    t.set_length(v, u(rng));
    t.set_radius(v, u(rng));
  }
  return t;
}

// ---- Independent oracle -------------------------------------------------------------------

struct Relations {
  std::vector<std::vector<char>> anc;  // anc[x][y]: x is y or an ancestor of y
  std::vector<std::vector<int>> lca;
};

Relations relations(const TreeGraph& t) {
  const int n = static_cast<int>(t.size());
  Relations r;
  r.anc.assign(n, std::vector<char>(n, 0));
  for (int y = 0; y < n; ++y) {
    for (int x = y;; x = static_cast<int>(t.parent(x))) {
      r.anc[x][y] = 1;
      if (x == 0) break;
    }
  }
  r.lca.assign(n, std::vector<int>(n, 0));
  for (int x = 0; x < n; ++x) {
    for (int y = 0; y < n; ++y) {
      int best = 0;
      for (int z = 0; z < n; ++z) {
        if (r.anc[z][x] && r.anc[z][y] && r.anc[best][z]) best = z;
      }
      r.lca[x][y] = best;
    }
  }
  return r;
}

struct Oracle {
  const TreeGraph& a;
  const TreeGraph& b;
  const EditCostModel& costs;
  bool constrained = true;
  Relations ra = relations(a), rb = relations(b);

  bool proper(const Relations& r, int x, int y) const { return x != y && r.anc[x][y]; }

  // Conditions on a set of pairs: eq. 4.19 is guaranteed by construction (one-to-one);
  // eq. 4.20 ancestor iff ancestor; eq. 4.21 lca(v,w) proper ancestor of u on both sides alike.
  bool valid_with(const std::vector<std::pair<int, int>>& m, std::pair<int, int> p) const {
    for (const auto& q : m) {
      if (ra.anc[q.first][p.first] != rb.anc[q.second][p.second]) return false;
      if (ra.anc[p.first][q.first] != rb.anc[p.second][q.second]) return false;
    }
    if (!constrained) return true;
    auto all = m;
    all.push_back(p);
    const std::size_t k = all.size() - 1;
    for (std::size_t x = 0; x < all.size(); ++x) {
      for (std::size_t y = 0; y < all.size(); ++y) {
        for (std::size_t z = 0; z < all.size(); ++z) {
          if (x != k && y != k && z != k) continue;
          const int la = ra.lca[all[x].first][all[y].first];
          const int lb = rb.lca[all[x].second][all[y].second];
          if (proper(ra, la, all[z].first) != proper(rb, lb, all[z].second)) return false;
        }
      }
    }
    return true;
  }

  bool valid(const std::vector<std::pair<NodeId, NodeId>>& mapping) const {
    std::vector<std::pair<int, int>> m;
    std::set<int> used_a, used_b;
    for (const auto& [x, y] : mapping) {
      if (!used_a.insert(static_cast<int>(x)).second) return false;
      if (!used_b.insert(static_cast<int>(y)).second) return false;
      if (!valid_with(m, {static_cast<int>(x), static_cast<int>(y)})) return false;
      m.emplace_back(x, y);
    }
    return true;
  }

  double cost(const std::vector<std::pair<NodeId, NodeId>>& mapping) const {
    std::vector<char> ma(a.size(), 0), mb(b.size(), 0);
    double c = 0.0;
    for (const auto& [x, y] : mapping) {
      ma[x] = mb[y] = 1;
      c += costs.relabel_cost(x, y);
    }
    for (NodeId x = 0; x < a.size(); ++x) c += ma[x] ? 0.0 : costs.delete_cost(x);
    for (NodeId y = 0; y < b.size(); ++y) c += mb[y] ? 0.0 : costs.insert_cost(y);
    return c;
  }

  // Minimum of eq. 4.17 over all valid mappings, by exhaustive backtracking.
  double minimum() {
    std::vector<std::pair<int, int>> m;
    std::vector<char> used(b.size(), 0);
    double best = std::numeric_limits<double>::infinity();
    const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
    std::function<void(int, double)> go = [&](int x, double partial) {
      if (x == na) {
        double c = partial;
        for (int y = 0; y < nb; ++y) c += used[y] ? 0.0 : costs.insert_cost(y);
        best = std::min(best, c);
        return;
      }
      go(x + 1, partial + costs.delete_cost(x));
      for (int y = 0; y < nb; ++y) {
        if (used[y] || !valid_with(m, {x, y})) continue;
        used[y] = 1;
        m.emplace_back(x, y);
        go(x + 1, partial + costs.relabel_cost(x, y));
        m.pop_back();
        used[y] = 0;
      }
    };
    go(0, 0.0);
    return best;
  }
};

// Random costs obeying relabel <= delete + insert.
class RandomCostModel final : public EditCostModel {
 public:
  RandomCostModel(std::mt19937_64& rng, std::size_t na, std::size_t nb, double bound_factor = 1.0)
      : nb_(nb) {
    std::uniform_real_distribution<double> u(0.0, 3.0), f(0.0, 1.0);
    for (std::size_t i = 0; i < na; ++i) del_.push_back(u(rng));
    for (std::size_t j = 0; j < nb; ++j) ins_.push_back(u(rng));
    for (std::size_t i = 0; i < na; ++i) {
      for (std::size_t j = 0; j < nb; ++j)
        rel_.push_back(bound_factor * f(rng) * (del_[i] + ins_[j]));
    }
  }
  double delete_cost(NodeId a) const override { return del_[a]; }
  double insert_cost(NodeId b) const override { return ins_[b]; }
  double relabel_cost(NodeId a, NodeId b) const override { return rel_[a * nb_ + b]; }

 private:
  std::size_t nb_;
  std::vector<double> del_, ins_, rel_;
};

// ---- Tests -------------------------------------------------------------------------------

TEST(ConstrainedEditDistance, MatchesBruteForceOnRandomSmallTrees) {
  std::mt19937_64 rng(20261122);
  const std::vector<std::string> label{"label"};
  for (int trial = 0; trial < 800; ++trial) {
    const TreeGraph a = random_tree(rng, std::uniform_int_distribution<int>(1, 8)(rng));
    const TreeGraph b = random_tree(rng, std::uniform_int_distribution<int>(1, 8)(rng));
    const int kind = trial % 4;
    EditDistanceOptions opt;
    opt.with_mapping = true;
    std::unique_ptr<EditCostModel> model;
    if (kind == 3) {
      model = std::make_unique<RandomCostModel>(rng, a.size(), b.size());
    } else {
      opt.cost = kind == 0 ? EditCostKind::kTopological
                           : (kind == 1 ? EditCostKind::kAbsolute : EditCostKind::kStandardized);
      if (kind == 1) opt.attributes = label;
      model =
          std::make_unique<FeatureCostModel>(make_edit_cost_model(opt.cost, a, b, opt.attributes));
    }
    Oracle oracle{a, b, *model};
    const double expected = oracle.minimum();
    const auto got = constrained_edit_distance(a, b, *model, opt);
    ASSERT_NEAR(got.distance, expected, 1e-9) << "trial " << trial << " kind " << kind;
    // The returned mapping is a valid constrained mapping and costs the distance.
    EXPECT_TRUE(oracle.valid(got.mapping)) << "trial " << trial;
    EXPECT_NEAR(oracle.cost(got.mapping), got.distance, 1e-9) << "trial " << trial;
    if (kind != 3) {
      EXPECT_NEAR(constrained_edit_distance(a, b, opt).distance, expected, 1e-9);
    }
  }
}

TEST(ConstrainedEditDistance, MinCostFlowAndHungarianAgree) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    // Bushy trees so that forests of several children are matched.
    std::vector<int> pa{-1}, pb{-1};
    const int na = std::uniform_int_distribution<int>(10, 40)(rng);
    const int nb = std::uniform_int_distribution<int>(10, 40)(rng);
    for (int v = 1; v < na; ++v)
      pa.push_back(std::uniform_int_distribution<int>(0, (v - 1) / 4)(rng));
    for (int v = 1; v < nb; ++v)
      pb.push_back(std::uniform_int_distribution<int>(0, (v - 1) / 4)(rng));
    const TreeGraph a = tree_from_parents(pa), b = tree_from_parents(pb);
    const RandomCostModel model(rng, a.size(), b.size());
    EditDistanceOptions opt;
    opt.with_mapping = true;
    opt.solver = AssignmentSolver::kHungarian;
    const auto h = constrained_edit_distance(a, b, model, opt);
    opt.solver = AssignmentSolver::kMinCostFlow;
    const auto f = constrained_edit_distance(a, b, model, opt);
    EXPECT_NEAR(h.distance, f.distance, 1e-9) << "trial " << trial;
    Oracle oracle{a, b, model};
    EXPECT_NEAR(oracle.cost(f.mapping), f.distance, 1e-9);
    EXPECT_NEAR(oracle.cost(h.mapping), h.distance, 1e-9);
  }
}

TEST(ConstrainedEditDistance, Symmetric) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 60; ++trial) {
    const TreeGraph a = random_tree(rng, std::uniform_int_distribution<int>(1, 60)(rng));
    const TreeGraph b = random_tree(rng, std::uniform_int_distribution<int>(1, 60)(rng));
    for (const auto kind :
         {EditCostKind::kTopological, EditCostKind::kAbsolute, EditCostKind::kStandardized}) {
      EditDistanceOptions opt;
      opt.cost = kind;
      const double ab = constrained_edit_distance(a, b, opt).distance;
      const double ba = constrained_edit_distance(b, a, opt).distance;
      EXPECT_NEAR(ab, ba, 1e-9 * std::max(1.0, ab));
    }
    EXPECT_EQ(constrained_edit_distance(a, a).distance, 0.0);
  }
}

// Rebuilds a tree with every node's children added in a shuffled order (ids change).
TreeGraph shuffle_children(const TreeGraph& t, std::mt19937_64& rng) {
  TreeGraph out;
  out.add_attribute("label");
  std::vector<std::pair<NodeId, NodeId>> queue{{0, kNoNode}};  // (old node, new parent)
  while (!queue.empty()) {
    const auto [old, parent] = queue.back();
    queue.pop_back();
    NodeData d = t.data(old);
    const NodeId n = out.add_node(parent, d);
    out.attribute("label")[n] = t.attribute("label")[old];
    std::vector<NodeId> kids(t.children(old).begin(), t.children(old).end());
    std::shuffle(kids.begin(), kids.end(), rng);
    for (const NodeId c : kids) queue.emplace_back(c, n);
  }
  return out;
}

TEST(ConstrainedEditDistance, InvariantToChildOrder) {
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const TreeGraph a = random_tree(rng, std::uniform_int_distribution<int>(2, 80)(rng));
    const TreeGraph b = random_tree(rng, std::uniform_int_distribution<int>(2, 80)(rng));
    const TreeGraph a2 = shuffle_children(a, rng), b2 = shuffle_children(b, rng);
    ASSERT_EQ(a2.size(), a.size());
    for (const auto kind : {EditCostKind::kTopological, EditCostKind::kAbsolute}) {
      EditDistanceOptions opt;
      opt.cost = kind;
      if (kind == EditCostKind::kAbsolute) opt.attributes = {"label", "length"};
      const double d = constrained_edit_distance(a, b, opt).distance;
      EXPECT_NEAR(constrained_edit_distance(a2, b2, opt).distance, d, 1e-9 * std::max(1.0, d));
      EXPECT_NEAR(constrained_edit_distance(a2, b, opt).distance, d, 1e-9 * std::max(1.0, d));
    }
  }
}

// T1 = r(x(b, c), d), T2 = r(b, c, d). Deleting x costs 1 without constraints, but it would
// merge the disjoint subtrees {b, c} and {d}; the constrained mapping must keep x's subtree
// apart: match x's subtree with one child of T2, so x->b (or b->b) with c deleted, d->d and the
// remaining child of T2 inserted: 1 + 1 + 1 = 3 (topological costs).
TEST(ConstrainedEditDistance, HandCaseWhereDeletingAnInnerNodeIsForbidden) {
  const TreeGraph t1 = tree_from_parents({-1, 0, 1, 1, 0});
  const TreeGraph t2 = tree_from_parents({-1, 0, 0, 0});
  EXPECT_EQ(constrained_edit_distance(t1, t2).distance, 3.0);
  const FeatureCostModel topo = make_edit_cost_model(EditCostKind::kTopological, t1, t2);
  Oracle unconstrained{t1, t2, topo};
  unconstrained.constrained = false;
  EXPECT_EQ(unconstrained.minimum(), 1.0);  // Tai's mapping: delete x only
  Oracle constrained{t1, t2, topo};
  EXPECT_EQ(constrained.minimum(), 3.0);
}

// The example of the command line, A = 1000(100, X=1(200, 300)), B = 1000(Y=2(100, 200), 300).
// Unconstrained, 100, 200 and 300 map to themselves, X is deleted (1) and Y inserted (2): 3.
// Constrained, that mapping would merge A's disjoint subtrees {100} and X(200, 300) under Y.
// The cheapest constrained mapping deletes X and A's 100 (1 + 100), so X's children join the
// root's forest, maps 200 -> 200 (under Y, inserted: 2) and 300 -> 300, and inserts B's 100
// (100): 203, with the matched pairs 1000, 200, 300.
TEST(ConstrainedEditDistance, HandCaseNewickLabels) {
  const TreeGraph a = parse_newick("(100,(200,300)1)1000;");
  const TreeGraph b = parse_newick("((100,200)2,300)1000;");
  EditDistanceOptions opt;
  opt.cost = EditCostKind::kAbsolute;
  opt.attributes = {"label"};
  opt.with_mapping = true;
  const auto r = constrained_edit_distance(a, b, opt);
  EXPECT_EQ(r.distance, 203.0);
  EXPECT_EQ(r.nodes_a, 5u);
  const auto label = [](const TreeGraph& t, NodeId n) { return t.attribute("label")[n]; };
  ASSERT_EQ(r.mapping.size(), 3u);
  for (const auto& [x, y] : r.mapping) EXPECT_EQ(label(a, x), label(b, y));
  const FeatureCostModel model =
      make_edit_cost_model(EditCostKind::kAbsolute, a, b, opt.attributes);
  Oracle unconstrained{a, b, model};
  unconstrained.constrained = false;
  EXPECT_EQ(unconstrained.minimum(), 3.0);
  Oracle constrained{a, b, model};
  EXPECT_EQ(constrained.minimum(), 203.0);
}

// Named trees need no numbers for the topological cost (delete = insert = 1, relabel = 0): the
// distance is |A| + |B| - 2 m for the largest constrained mapping of m pairs.
// A = r(C(A, B), D), 5 nodes, embeds in B = r(C(A, B), F(D, E)), 7 nodes: m = 5 (D maps into F's
// subtree, disjoint from C's), so 5 + 7 - 10 = 2, and no mapping does better than the 2 extra
// nodes of B.
// A = r(x(b, c), d), B = r(b, c, d): deleting x would merge {b, c} with {d}, so at most r, one of
// x's subtree and d match: m = 3, 5 + 4 - 6 = 3.
TEST(ConstrainedEditDistance, HandCaseNamedNewickTopological) {
  const NamedTree a = parse_newick_named("((A:1,B:2)C:0.5,D:1);");
  const NamedTree b = parse_newick_named("((A,B)C,(D,E)F);");
  EditDistanceOptions opt;
  opt.with_mapping = true;
  const auto r = constrained_edit_distance(a.tree, b.tree, opt);
  EXPECT_EQ(r.distance, 2.0);
  EXPECT_EQ(r.nodes_a, 5u);
  EXPECT_EQ(r.nodes_b, 7u);
  EXPECT_EQ(r.mapping.size(), 5u);  // every node of A is matched
  const TreeGraph x = parse_newick("((b,c)x,d)r;");
  const TreeGraph y = parse_newick("(b,c,d)r;");
  EXPECT_EQ(constrained_edit_distance(x, y).distance, 3.0);
  EXPECT_EQ(constrained_edit_distance(y, x).distance, 3.0);
}

TEST(ConstrainedEditDistance, RejectsCostModelBreakingTheRelabelBound) {
  std::mt19937_64 rng(3);
  const TreeGraph a = random_tree(rng, 6), b = random_tree(rng, 6);
  const RandomCostModel bad(rng, a.size(), b.size(), 5.0);  // relabel up to 5 (del + ins)
  EXPECT_THROW(constrained_edit_distance(a, b, bad), ValueError);
}

TEST(ConstrainedEditDistance, EmptyTreesCostAllInsertions) {
  std::mt19937_64 rng(1);
  const TreeGraph a = random_tree(rng, 7), empty;
  EXPECT_EQ(constrained_edit_distance(a, empty).distance, 7.0);
  EXPECT_EQ(constrained_edit_distance(empty, a).distance, 7.0);
  EXPECT_EQ(constrained_edit_distance(empty, empty).distance, 0.0);
}

TEST(ConstrainedEditDistance, MainSkeletonComparesOnlyThickNodes) {
  // Trunk 0-1-2 of radius 0.5 with thin twigs; the skeleton (radius > 0.1) is a chain of 3.
  TreeGraph a = tree_from_parents({-1, 0, 1, 0, 1, 2, 2});
  TreeGraph b = tree_from_parents({-1, 0, 1, 2, 0});
  for (NodeId v = 0; v < a.size(); ++v) a.set_radius(v, v <= 2 ? 0.5 : 0.05);
  for (NodeId v = 0; v < b.size(); ++v) b.set_radius(v, v <= 2 ? 0.5 : 0.05);
  // A thick node under a thin one is not part of the skeleton either.
  b.set_radius(3, 0.5);
  b.set_radius(2, 0.05);
  EditDistanceOptions opt;
  opt.main_skeleton_radius_m = 0.1;
  const auto r = constrained_edit_distance(a, b, opt);
  EXPECT_EQ(r.nodes_a, 3u);
  EXPECT_EQ(r.nodes_b, 2u);
  EXPECT_EQ(r.distance, 1.0);  // a chain of 3 against a chain of 2
  EXPECT_EQ(main_skeleton_nodes(b, 0.1), (std::vector<NodeId>{0, 1}));
}

// ---- Normalized distance: distance / (delete all of A + insert all of B) ----------------------

TEST(NormalizedEditDistance, IdenticalTreesAreZero) {
  std::mt19937_64 rng(11);
  const TreeGraph a = random_tree(rng, 9);
  for (const EditCostKind kind : kEditCostKinds) {
    EditDistanceOptions opt;
    opt.cost = kind;
    const auto r = constrained_edit_distance(a, a, opt);
    EXPECT_EQ(r.distance, 0.0);
    EXPECT_EQ(r.normalized, 0.0);
    EXPECT_GT(r.deletion_cost_a + r.insertion_cost_b, 0.0);
  }
}

// Relabelling costs exactly delete + insert for every pair: no mapping beats the empty one, so
// the distance is the whole deletion and insertion cost and the normalized distance 1.
class NothingInCommon final : public EditCostModel {
 public:
  double delete_cost(NodeId a) const override { return 1.0 + a; }
  double insert_cost(NodeId b) const override { return 2.0 + 0.5 * b; }
  double relabel_cost(NodeId a, NodeId b) const override { return delete_cost(a) + insert_cost(b); }
};

TEST(NormalizedEditDistance, NothingInCommonIsOne) {
  std::mt19937_64 rng(12);
  const TreeGraph a = random_tree(rng, 6), b = random_tree(rng, 8);
  const auto r = constrained_edit_distance(a, b, NothingInCommon{});
  EXPECT_DOUBLE_EQ(r.deletion_cost_a, 6.0 + 15.0);        // sum of 1 + a, a = 0..5
  EXPECT_DOUBLE_EQ(r.insertion_cost_b, 16.0 + 0.5 * 28);  // sum of 2 + b / 2, b = 0..7
  EXPECT_DOUBLE_EQ(r.distance, 51.0);
  EXPECT_DOUBLE_EQ(r.normalized, 1.0);
  // Against an empty tree everything is deleted: 1 as well; two empty trees are identical.
  const TreeGraph empty;
  EXPECT_EQ(constrained_edit_distance(a, empty).normalized, 1.0);
  EXPECT_EQ(constrained_edit_distance(empty, empty).normalized, 0.0);
}

// Absolute costs on labels: A's labels all 0, so deleting A costs nothing and matching any node
// of B costs its label, as inserting it does. The distance is B's label sum, the normalized
// distance 1.
TEST(NormalizedEditDistance, ZeroLabelsAgainstPositiveOnesIsOne) {
  EditDistanceOptions opt;
  opt.cost = EditCostKind::kAbsolute;
  opt.attributes = {"label"};
  const auto r = constrained_edit_distance(parse_newick("(0,0)0;"), parse_newick("(5,7)3;"), opt);
  EXPECT_EQ(r.distance, 15.0);
  EXPECT_EQ(r.normalized, 1.0);
}

// The hand cases above divided by hand: labels of A sum to 1601, of B to 1602 (absolute costs
// have no unit cost), distance 203; topological, 2 against 5 + 7 nodes.
TEST(NormalizedEditDistance, HandCases) {
  EditDistanceOptions opt;
  opt.cost = EditCostKind::kAbsolute;
  opt.attributes = {"label"};
  const auto r = constrained_edit_distance(parse_newick("(100,(200,300)1)1000;"),
                                           parse_newick("((100,200)2,300)1000;"), opt);
  EXPECT_EQ(r.deletion_cost_a, 1601.0);
  EXPECT_EQ(r.insertion_cost_b, 1602.0);
  EXPECT_DOUBLE_EQ(r.normalized, 203.0 / 3203.0);
  const auto t = constrained_edit_distance(parse_newick_named("((A:1,B:2)C:0.5,D:1);").tree,
                                           parse_newick_named("((A,B)C,(D,E)F);").tree);
  EXPECT_DOUBLE_EQ(t.normalized, 2.0 / 12.0);
  EXPECT_EQ(normalized_edit_distance(0.0, 0.0, 0.0), 0.0);
}

TEST(NormalizedEditDistance, StaysWithinZeroAndOneOnRandomTrees) {
  std::mt19937_64 rng(13);
  for (int k = 0; k < 50; ++k) {
    const TreeGraph a = random_tree(rng, 1 + k % 9), b = random_tree(rng, 1 + (k * 7) % 11);
    EditDistanceOptions opt;
    opt.cost = kEditCostKinds[k % 3];
    const auto r = constrained_edit_distance(a, b, opt);
    EXPECT_GE(r.normalized, 0.0);
    EXPECT_LE(r.normalized, 1.0);
    EXPECT_LE(r.distance, r.deletion_cost_a + r.insertion_cost_b + 1e-9);
  }
}

TEST(EditCostModel, StandardizedFollowsPirkEquations) {
  // Lengths 1, 2 (tree A) and 3, 6 (tree B): mean 3, sd sqrt((4+1+0+9)/3).
  TreeGraph a = tree_from_parents({-1, 0}), b = tree_from_parents({-1, 0});
  a.set_length(0, 1);
  a.set_length(1, 2);
  b.set_length(0, 3);
  b.set_length(1, 6);
  const std::vector<std::string> attrs{"length"};
  const auto m = make_edit_cost_model(EditCostKind::kStandardized, a, b, attrs);
  const double sd = std::sqrt(14.0 / 3.0);
  EXPECT_NEAR(m.delete_cost(0), 2.0 / sd, 1e-12);
  EXPECT_NEAR(m.insert_cost(1), 3.0 / sd, 1e-12);
  EXPECT_NEAR(m.relabel_cost(1, 1), 4.0 / sd, 1e-12);
  EXPECT_THROW(
      make_edit_cost_model(EditCostKind::kAbsolute, a, b, std::vector<std::string>{"nope"}),
      ValueError);
  EXPECT_THROW(edit_cost_kind_from_name("euclid"), ValueError);
}

}  // namespace
}  // namespace fspm
