#include "fspm/constrained_edit_distance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <string>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm {
namespace {

// Traceback codes, in the low 2 bits; the child index sits above them.
constexpr std::uint16_t kCodeMatch = 0;   // tree: relabel i -> j; forest: restricted mapping
constexpr std::uint16_t kCodeInsert = 1;  // node j_t of B inserted, A's side maps under j_t
constexpr std::uint16_t kCodeDelete = 2;  // node i_s of A deleted, B's side maps under i_s
constexpr std::uint16_t kCodeNone = 3;    // nothing matched (a forest against an empty one)
constexpr std::size_t kMaxTracebackDegree = (1u << 14) - 1;

std::uint16_t encode(std::uint16_t code, std::uint32_t index) {
  return static_cast<std::uint16_t>(code | (index << 2));
}

// A tree renumbered in post-order (children before parents) with children as one flat array.
struct PostTree {
  std::vector<NodeId> original;      // post-order index -> node id
  std::vector<std::uint32_t> first;  // children of i: kids[first[i] .. first[i+1])
  std::vector<std::uint32_t> kids;   // post-order indices
  std::uint32_t size() const { return static_cast<std::uint32_t>(original.size()); }
  std::uint32_t degree(std::uint32_t i) const { return first[i + 1] - first[i]; }
  const std::uint32_t* children(std::uint32_t i) const { return kids.data() + first[i]; }
};

// Children are ordered by decreasing Sethi-Ullman need (the most rows a subtree keeps alive at
// once), which keeps the number of pending rows of the programme small: a chain keeps one, a
// binary tree O(log n).
PostTree build_post_tree(const TreeGraph& t, const std::vector<char>& keep) {
  PostTree p;
  const std::size_t n = t.size();
  p.first.assign(1, 0);
  if (n == 0 || !keep[0]) return p;
  std::vector<std::uint32_t> off(n + 1, 0);
  for (NodeId v = 1; v < n; ++v) {
    if (keep[v]) ++off[t.parent(v) + 1];
  }
  for (std::size_t v = 0; v < n; ++v) off[v + 1] += off[v];
  std::vector<NodeId> kids(off[n]);
  std::vector<std::uint32_t> pos(off.begin(), off.end() - 1);
  for (NodeId v = 1; v < n; ++v) {
    if (keep[v]) kids[pos[t.parent(v)]++] = v;
  }
  std::vector<std::uint32_t> need(n, 1);
  for (std::size_t v = n; v-- > 0;) {
    if (!keep[v]) continue;
    auto* b = kids.data() + off[v];
    auto* e = kids.data() + off[v + 1];
    std::stable_sort(b, e, [&](NodeId x, NodeId y) { return need[x] > need[y]; });
    std::uint32_t k = 0, nv = static_cast<std::uint32_t>(e - b) + 1;
    for (auto* c = b; c != e; ++c, ++k) nv = std::max(nv, need[*c] + k);
    need[v] = nv;
  }
  std::vector<std::uint32_t> index(n, 0);
  std::vector<std::pair<NodeId, std::uint32_t>> stack{{0, 0}};
  while (!stack.empty()) {
    auto& [v, k] = stack.back();
    if (off[v] + k < off[v + 1]) {
      const NodeId c = kids[off[v] + k];
      ++k;
      stack.emplace_back(c, 0);
    } else {
      index[v] = static_cast<std::uint32_t>(p.original.size());
      p.original.push_back(v);
      stack.pop_back();
    }
  }
  for (const NodeId v : p.original) {
    for (std::uint32_t k = off[v]; k < off[v + 1]; ++k) p.kids.push_back(index[kids[k]]);
    p.first.push_back(static_cast<std::uint32_t>(p.kids.size()));
  }
  return p;
}

std::vector<char> keep_mask(const TreeGraph& t, const std::vector<NodeId>* subset) {
  std::vector<char> in(t.size(), subset ? 0 : 1);
  if (subset) {
    for (const NodeId v : *subset) in.at(v) = 1;
  }
  // Closed under ancestors, so the compared nodes form one tree rooted at the root.
  for (NodeId v = 1; v < t.size(); ++v) in[v] = in[v] && in[t.parent(v)];
  return in;
}

// Bytes the programme below allocates for A x B: two rows of |B| doubles for every node of A
// whose parent is still pending (at most `peak` at once, counted in post-order exactly as the
// programme takes and frees rows); one matching problem at a time between the children of two
// nodes (a gain matrix of doubles for the Hungarian solver; two Boost graph arcs with their
// properties, about 256 bytes, per pair for min-cost flow); and 3 x 2 bytes per node pair for
// the traceback.
double programme_bytes(const PostTree& A, std::uint32_t n2, std::uint32_t max_degree_b,
                       AssignmentSolver solver, bool with_mapping) {
  std::size_t live = 0, peak = 0;
  std::uint32_t max_degree_a = 0;
  for (std::uint32_t i = 0; i < A.size(); ++i) {
    peak = std::max(peak, ++live);
    live -= A.degree(i);
    max_degree_a = std::max(max_degree_a, A.degree(i));
  }
  const double rows = 2.0 * static_cast<double>(peak) * n2 * sizeof(double);
  const double matching = static_cast<double>(max_degree_a) * max_degree_b *
                          (solver == AssignmentSolver::kHungarian ? sizeof(double) : 256.0);
  const double pairs = static_cast<double>(A.size()) * n2;
  return rows + matching + (with_mapping ? pairs * 3 * sizeof(std::uint16_t) : 0.0);
}

struct Traceback {
  std::vector<std::uint16_t> tree, forest, match;  // [i * n2 + j]; match by child of A
};

template <int Dims>
struct FeatureRelabel {
  const double* fa;
  const double* fb;
  std::size_t dims;
  double operator()(std::uint32_t i, std::uint32_t j) const {
    if constexpr (Dims == 0) {
      return 0.0;
    } else {
      const std::size_t d = Dims > 0 ? static_cast<std::size_t>(Dims) : dims;
      double c = 0.0;
      for (std::size_t k = 0; k < d; ++k) c += std::abs(fa[i * d + k] - fb[j * d + k]);
      return c;
    }
  }
};

struct ModelRelabel {
  const EditCostModel* model;
  const NodeId* original_a;
  const NodeId* original_b;
  const double* del;
  const double* ins;
  double operator()(std::uint32_t i, std::uint32_t j) const {
    const NodeId a = original_a[i], b = original_b[j];
    const double r = model->relabel_cost(a, b);
    if (!std::isfinite(r) || r < 0.0) {
      throw ValueError("cost model: relabel cost of node " + std::to_string(a) + " of A to node " +
                       std::to_string(b) + " of B is " + std::to_string(r) +
                       "; expected a finite non-negative number");
    }
    const double bound = del[i] + ins[j];
    if (r > bound + 1e-12 * bound) {
      throw ValueError("cost model breaks relabel <= delete + insert: relabel(" +
                       std::to_string(a) + ", " + std::to_string(b) + ") = " + std::to_string(r) +
                       " > " + std::to_string(bound) +
                       "; the constrained edit distance is only exact under this bound");
    }
    return r;
  }
};

// Zhang's recurrences (Zhang 1996): rows of A in post-order, columns of B in post-order,
// D_T = distance of subtrees, D_F = distance of child forests. Only the rows of nodes whose
// parent is not done yet are alive; a finished parent returns its children's rows to a pool.
template <class Relabel>
class ZhangProgramme {
 public:
  ZhangProgramme(const PostTree& A, const PostTree& B, const std::vector<double>& del,
                 const std::vector<double>& ins, const Relabel& relabel, AssignmentSolver solver,
                 Traceback* tb)
      : A_(A), B_(B), relabel_(relabel), solver_(solver), tb_(tb), n1_(A.size()), n2_(B.size()) {
    whole_subtree_costs(del, ins);
  }

  double run() {
    if (n1_ == 0 || n2_ == 0) {
      return (n1_ ? del_tree_[n1_ - 1] : 0.0) + (n2_ ? ins_tree_[n2_ - 1] : 0.0);
    }
    tree_row_.assign(n1_, nullptr);
    forest_row_.assign(n1_, nullptr);
    double result = 0.0;
    for (std::uint32_t i = 0; i < n1_; ++i) {
      fill_row(i);
      if (i + 1 == n1_) result = tree_row_[i][n2_ - 1];
      release_children_rows(i);
    }
    return result;
  }

 private:
  // Costs of deleting / inserting whole subtrees and child forests.
  void whole_subtree_costs(const std::vector<double>& del, const std::vector<double>& ins) {
    del_tree_.resize(n1_);
    del_forest_.assign(n1_, 0.0);
    ins_tree_.resize(n2_);
    ins_forest_.assign(n2_, 0.0);
    for (std::uint32_t i = 0; i < n1_; ++i) {
      for (std::uint32_t s = 0; s < A_.degree(i); ++s) {
        del_forest_[i] += del_tree_[A_.children(i)[s]];
      }
      del_tree_[i] = del_forest_[i] + del[i];
    }
    for (std::uint32_t j = 0; j < n2_; ++j) {
      for (std::uint32_t t = 0; t < B_.degree(j); ++t) {
        ins_forest_[j] += ins_tree_[B_.children(j)[t]];
      }
      ins_tree_[j] = ins_forest_[j] + ins[j];
    }
  }

  double* take_row() {
    if (free_rows_.empty()) {
      storage_.push_back(std::make_unique<double[]>(n2_));
      return storage_.back().get();
    }
    double* r = free_rows_.back();
    free_rows_.pop_back();
    return r;
  }

  // D_F[i][.] and D_T[i][.] for every node of B, from the rows of i's children.
  void fill_row(std::uint32_t i) {
    double* Ti = tree_row_[i] = take_row();
    double* Fi = forest_row_[i] = take_row();
    ci_ = A_.children(i);
    ni_ = A_.degree(i);
    child_tree_.resize(ni_);
    child_forest_.resize(ni_);
    for (std::uint32_t s = 0; s < ni_; ++s) {
      child_tree_[s] = tree_row_[ci_[s]];
      child_forest_[s] = forest_row_[ci_[s]];
    }
    for (std::uint32_t j = 0; j < n2_; ++j) {
      std::uint16_t fcode = kCodeNone;
      const double f = forest_distance(i, j, Fi, fcode);
      Fi[j] = f;
      std::uint16_t tcode = kCodeMatch;
      Ti[j] = tree_distance(i, j, f, Ti, tcode);
      if (tb_) {
        tb_->tree[std::size_t{i} * n2_ + j] = tcode;
        tb_->forest[std::size_t{i} * n2_ + j] = fcode;
      }
    }
  }

  void release_children_rows(std::uint32_t i) {
    const std::uint32_t* ci = A_.children(i);
    for (std::uint32_t s = 0; s < A_.degree(i); ++s) {
      free_rows_.push_back(tree_row_[ci[s]]);
      free_rows_.push_back(forest_row_[ci[s]]);
      tree_row_[ci[s]] = forest_row_[ci[s]] = nullptr;
    }
  }

  // D_F(i, j): the restricted mapping of the two child forests, or all of one forest mapped
  // under a single child of the other node.
  double forest_distance(std::uint32_t i, std::uint32_t j, const double* Fi, std::uint16_t& fcode) {
    const std::uint32_t* cj = B_.children(j);
    const std::uint32_t nj = B_.degree(j);
    if (ni_ == 0) return ins_forest_[j];
    if (nj == 0) return del_forest_[i];
    fcode = kCodeMatch;
    double f = restricted_mapping(i, j);
    // All of A's forest maps into the forest under one child j_t of j; j_t is inserted.
    for (std::uint32_t t = 0; t < nj; ++t) {
      const double c = ins_forest_[j] - ins_forest_[cj[t]] + Fi[cj[t]];
      if (c < f) {
        f = c;
        fcode = encode(kCodeInsert, t);
      }
    }
    // Symmetric: all of B's forest maps into the forest under one child i_s of i.
    for (std::uint32_t s = 0; s < ni_; ++s) {
      const double c = del_forest_[i] - del_forest_[ci_[s]] + child_forest_[s][j];
      if (c < f) {
        f = c;
        fcode = encode(kCodeDelete, s);
      }
    }
    return f;
  }

  // D_T(i, j): i relabelled to j with the forests matched, or j inserted with T_A[i] inside one
  // child subtree of j, or i deleted symmetrically.
  double tree_distance(std::uint32_t i, std::uint32_t j, double f, const double* Ti,
                       std::uint16_t& tcode) const {
    const std::uint32_t* cj = B_.children(j);
    const std::uint32_t nj = B_.degree(j);
    double d = f + relabel_(i, j);
    for (std::uint32_t t = 0; t < nj; ++t) {
      const double c = ins_tree_[j] - ins_tree_[cj[t]] + Ti[cj[t]];
      if (c < d) {
        d = c;
        tcode = encode(kCodeInsert, t);
      }
    }
    for (std::uint32_t s = 0; s < ni_; ++s) {
      const double c = del_tree_[i] - del_tree_[ci_[s]] + child_tree_[s][j];
      if (c < d) {
        d = c;
        tcode = encode(kCodeDelete, s);
      }
    }
    return d;
  }

  // Restricted mapping: children of i matched one-to-one with children of j.
  double restricted_mapping(std::uint32_t i, std::uint32_t j) {
    if (solver_ == AssignmentSolver::kMinCostFlow) return match_by_flow(j);
    const std::uint32_t nj = B_.degree(j);
    if (ni_ == 1 || nj == 1) return match_one_pair(i, j);
    return match_by_assignment(i, j);
  }

  double match_by_flow(std::uint32_t j) {
    const std::uint32_t* cj = B_.children(j);
    const std::uint32_t nj = B_.degree(j);
    pair_cost_.resize(std::size_t{ni_} * nj);
    row_alone_.resize(ni_);
    col_alone_.resize(nj);
    for (std::uint32_t s = 0; s < ni_; ++s) {
      row_alone_[s] = del_tree_[ci_[s]];
      for (std::uint32_t t = 0; t < nj; ++t) pair_cost_[s * nj + t] = child_tree_[s][cj[t]];
    }
    for (std::uint32_t t = 0; t < nj; ++t) col_alone_[t] = ins_tree_[cj[t]];
    const auto pa = solve_partial_assignment(pair_cost_, ni_, nj, row_alone_, col_alone_, solver_);
    if (tb_) {
      for (std::uint32_t s = 0; s < ni_; ++s) {
        tb_->match[std::size_t{ci_[s]} * n2_ + j] =
            static_cast<std::uint16_t>(pa.row_to_col[s] + 1);
      }
    }
    return pa.cost;
  }

  // One side has a single child: the best pair, if it gains anything, by enumeration.
  double match_one_pair(std::uint32_t i, std::uint32_t j) {
    const std::uint32_t* cj = B_.children(j);
    const std::uint32_t nj = B_.degree(j);
    double best = 0.0;
    std::uint32_t bs = ni_, bt = nj;
    for (std::uint32_t s = 0; s < ni_; ++s) {
      for (std::uint32_t t = 0; t < nj; ++t) {
        const double g = child_tree_[s][cj[t]] - del_tree_[ci_[s]] - ins_tree_[cj[t]];
        if (g <= best) {
          best = g;
          bs = s;
          bt = t;
        }
      }
    }
    if (tb_) {
      for (std::uint32_t s = 0; s < ni_; ++s) {
        tb_->match[std::size_t{ci_[s]} * n2_ + j] =
            static_cast<std::uint16_t>(s == bs ? bt + 1 : 0);
      }
    }
    return del_forest_[i] + ins_forest_[j] + best;
  }

  // Gains (pair cost minus leaving both alone, clamped at 0), smaller side as rows, solved by
  // the Hungarian method.
  double match_by_assignment(std::uint32_t i, std::uint32_t j) {
    const std::uint32_t* cj = B_.children(j);
    const std::uint32_t nj = B_.degree(j);
    const bool transposed = ni_ > nj;
    const std::uint32_t rows = transposed ? nj : ni_, cols = transposed ? ni_ : nj;
    gain_.resize(std::size_t{rows} * cols);
    assign_.resize(rows);
    for (std::uint32_t s = 0; s < ni_; ++s) {
      for (std::uint32_t t = 0; t < nj; ++t) {
        const double g =
            std::min(0.0, child_tree_[s][cj[t]] - del_tree_[ci_[s]] - ins_tree_[cj[t]]);
        gain_[transposed ? std::size_t{t} * cols + s : std::size_t{s} * cols + t] = g;
      }
    }
    const double f = del_forest_[i] + ins_forest_[j] +
                     hungarian_.solve(gain_.data(), rows, cols, assign_.data());
    if (tb_) {
      for (std::uint32_t s = 0; s < ni_; ++s) tb_->match[std::size_t{ci_[s]} * n2_ + j] = 0;
      for (std::uint32_t r = 0; r < rows; ++r) {
        const std::uint32_t s = transposed ? static_cast<std::uint32_t>(assign_[r]) : r;
        const std::uint32_t t = transposed ? r : static_cast<std::uint32_t>(assign_[r]);
        if (child_tree_[s][cj[t]] <= del_tree_[ci_[s]] + ins_tree_[cj[t]]) {
          tb_->match[std::size_t{ci_[s]} * n2_ + j] = static_cast<std::uint16_t>(t + 1);
        }
      }
    }
    return f;
  }

  const PostTree& A_;
  const PostTree& B_;
  const Relabel& relabel_;
  const AssignmentSolver solver_;
  Traceback* const tb_;
  const std::uint32_t n1_, n2_;
  std::vector<double> del_tree_, del_forest_, ins_tree_, ins_forest_;
  // Rows of D_T and D_F per node of A, alive until its parent is done, and their pool.
  std::vector<std::unique_ptr<double[]>> storage_;
  std::vector<double*> free_rows_, tree_row_, forest_row_;
  // The node of A whose row is being filled: its children and their rows.
  const std::uint32_t* ci_ = nullptr;
  std::uint32_t ni_ = 0;
  std::vector<const double*> child_tree_, child_forest_;
  // Workspaces of the restricted mapping.
  std::vector<double> gain_, pair_cost_, row_alone_, col_alone_;
  std::vector<int> assign_;
  HungarianWorkspace hungarian_;
};

template <class Relabel>
double run_programme(const PostTree& A, const PostTree& B, const std::vector<double>& del,
                     const std::vector<double>& ins, const Relabel& relabel,
                     AssignmentSolver solver, Traceback* tb) {
  return ZhangProgramme<Relabel>(A, B, del, ins, relabel, solver, tb).run();
}

std::vector<std::pair<NodeId, NodeId>> trace_mapping(const PostTree& A, const PostTree& B,
                                                     const Traceback& tb) {
  std::vector<std::pair<NodeId, NodeId>> mapping;
  const std::size_t n2 = B.size();
  struct Step {
    bool tree;
    std::uint32_t i, j;
  };
  std::vector<Step> stack{{true, A.size() - 1, B.size() - 1}};
  while (!stack.empty()) {
    const Step st = stack.back();
    stack.pop_back();
    const std::size_t at = std::size_t{st.i} * n2 + st.j;
    const std::uint16_t v = st.tree ? tb.tree[at] : tb.forest[at];
    const std::uint16_t code = v & 3u;
    const std::uint32_t index = v >> 2;
    if (code == kCodeNone) continue;
    if (code == kCodeInsert) {
      stack.push_back({st.tree, st.i, B.children(st.j)[index]});
    } else if (code == kCodeDelete) {
      stack.push_back({st.tree, A.children(st.i)[index], st.j});
    } else if (st.tree) {
      mapping.emplace_back(A.original[st.i], B.original[st.j]);
      stack.push_back({false, st.i, st.j});
    } else {
      for (std::uint32_t s = 0; s < A.degree(st.i); ++s) {
        const std::uint32_t c = A.children(st.i)[s];
        const std::uint16_t m = tb.match[std::size_t{c} * n2 + st.j];
        if (m != 0) stack.push_back({true, c, B.children(st.j)[m - 1u]});
      }
    }
  }
  std::sort(mapping.begin(), mapping.end());
  return mapping;
}

std::uint32_t max_degree(const PostTree& t) {
  std::uint32_t d = 0;
  for (std::uint32_t i = 0; i < t.size(); ++i) d = std::max(d, t.degree(i));
  return d;
}

EditDistanceResult compute(const TreeGraph& a, const TreeGraph& b, const EditCostModel& costs,
                           const EditDistanceOptions& options, const std::vector<NodeId>* subset_a,
                           const std::vector<NodeId>* subset_b) {
  const PostTree A = build_post_tree(a, keep_mask(a, subset_a));
  const PostTree B = build_post_tree(b, keep_mask(b, subset_b));
  const std::uint32_t n1 = A.size(), n2 = B.size();
  std::vector<double> del(n1), ins(n2);
  const auto checked = [](double c, const char* op, NodeId n, const char* tree) {
    if (!std::isfinite(c) || c < 0.0) {
      throw ValueError(std::string("cost model: ") + op + " cost of node " + std::to_string(n) +
                       " of " + tree + " is " + std::to_string(c) +
                       "; expected a finite non-negative number");
    }
    return c;
  };
  for (std::uint32_t i = 0; i < n1; ++i) {
    del[i] = checked(costs.delete_cost(A.original[i]), "delete", A.original[i], "A");
  }
  for (std::uint32_t j = 0; j < n2; ++j) {
    ins[j] = checked(costs.insert_cost(B.original[j]), "insert", B.original[j], "B");
  }

  EditDistanceResult result;
  result.nodes_a = n1;
  result.nodes_b = n2;
  result.deletion_cost_a = std::accumulate(del.begin(), del.end(), 0.0);
  result.insertion_cost_b = std::accumulate(ins.begin(), ins.end(), 0.0);
  check_memory(programme_bytes(A, n2, max_degree(B), options.solver, options.with_mapping),
               "the edit distance of trees of " + std::to_string(n1) + " and " +
                   std::to_string(n2) + " nodes");
  Traceback tb;
  Traceback* tbp = nullptr;
  if (options.with_mapping && n1 > 0 && n2 > 0) {
    if (max_degree(A) > kMaxTracebackDegree || max_degree(B) > kMaxTracebackDegree) {
      throw ValueError("the edit mapping supports nodes with at most " +
                       std::to_string(kMaxTracebackDegree) + " children");
    }
    const std::size_t cells = std::size_t{n1} * n2;
    tb.tree.assign(cells, kCodeNone);
    tb.forest.assign(cells, kCodeNone);
    tb.match.assign(cells, 0);
    tbp = &tb;
  }

  const auto* features = dynamic_cast<const FeatureCostModel*>(&costs);
  if (features) {
    // Features in post-order, contiguous, for the inlined Manhattan relabel.
    const std::size_t d = features->dims();
    std::vector<double> fa(std::size_t{n1} * d), fb(std::size_t{n2} * d);
    for (std::uint32_t i = 0; i < n1; ++i) {
      std::ranges::copy(features->features_a(A.original[i]), fa.begin() + i * d);
    }
    for (std::uint32_t j = 0; j < n2; ++j) {
      std::ranges::copy(features->features_b(B.original[j]), fb.begin() + j * d);
    }
    switch (d) {
      case 0:
        result.distance = run_programme(A, B, del, ins, FeatureRelabel<0>{nullptr, nullptr, 0},
                                        options.solver, tbp);
        break;
      case 1:
        result.distance = run_programme(A, B, del, ins, FeatureRelabel<1>{fa.data(), fb.data(), 1},
                                        options.solver, tbp);
        break;
      case 2:
        result.distance = run_programme(A, B, del, ins, FeatureRelabel<2>{fa.data(), fb.data(), 2},
                                        options.solver, tbp);
        break;
      default:
        result.distance = run_programme(A, B, del, ins, FeatureRelabel<-1>{fa.data(), fb.data(), d},
                                        options.solver, tbp);
    }
  } else {
    const ModelRelabel relabel{&costs, A.original.data(), B.original.data(), del.data(),
                               ins.data()};
    result.distance = run_programme(A, B, del, ins, relabel, options.solver, tbp);
  }
  if (tbp) result.mapping = trace_mapping(A, B, tb);
  result.normalized =
      normalized_edit_distance(result.distance, result.deletion_cost_a, result.insertion_cost_b);
  return result;
}

}  // namespace

double normalized_edit_distance(double distance, double deletion_cost_a, double insertion_cost_b) {
  const double scale = deletion_cost_a + insertion_cost_b;
  if (!(scale > 0.0)) return 0.0;
  return std::clamp(distance / scale, 0.0, 1.0);
}

std::vector<NodeId> main_skeleton_nodes(const TreeGraph& tree, double min_radius_m) {
  std::vector<NodeId> nodes;
  std::vector<char> keep(tree.size(), 0);
  for (NodeId v = 0; v < tree.size(); ++v) {
    keep[v] = tree.radius(v) > min_radius_m && (v == 0 || keep[tree.parent(v)]);
    if (keep[v]) nodes.push_back(v);
  }
  return nodes;
}

EditDistanceResult constrained_edit_distance(const TreeGraph& a, const TreeGraph& b,
                                             const EditDistanceOptions& options) {
  std::optional<std::vector<NodeId>> sa, sb;
  if (options.main_skeleton_radius_m) {
    sa = main_skeleton_nodes(a, *options.main_skeleton_radius_m);
    sb = main_skeleton_nodes(b, *options.main_skeleton_radius_m);
  }
  const FeatureCostModel costs = make_edit_cost_model(options.cost, a, b, options.attributes,
                                                      sa ? &*sa : nullptr, sb ? &*sb : nullptr);
  return compute(a, b, costs, options, sa ? &*sa : nullptr, sb ? &*sb : nullptr);
}

EditDistanceResult constrained_edit_distance(const TreeGraph& a, const TreeGraph& b,
                                             const EditCostModel& costs,
                                             const EditDistanceOptions& options) {
  std::optional<std::vector<NodeId>> sa, sb;
  if (options.main_skeleton_radius_m) {
    sa = main_skeleton_nodes(a, *options.main_skeleton_radius_m);
    sb = main_skeleton_nodes(b, *options.main_skeleton_radius_m);
  }
  return compute(a, b, costs, options, sa ? &*sa : nullptr, sb ? &*sb : nullptr);
}

}  // namespace fspm
