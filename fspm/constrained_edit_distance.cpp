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

// Zhang's recurrences (Zhang 1996): rows of A in post-order, columns of B in
// post-order, D_T = distance of subtrees, D_F = distance of child forests.
template <class Relabel>
double run_programme(const PostTree& A, const PostTree& B, const std::vector<double>& del,
                     const std::vector<double>& ins, const Relabel& relabel,
                     AssignmentSolver solver, Traceback* tb) {
  const std::uint32_t n1 = A.size(), n2 = B.size();
  // Costs of deleting / inserting whole subtrees and child forests.
  std::vector<double> del_tree(n1), del_forest(n1, 0.0), ins_tree(n2), ins_forest(n2, 0.0);
  for (std::uint32_t i = 0; i < n1; ++i) {
    for (std::uint32_t s = 0; s < A.degree(i); ++s) del_forest[i] += del_tree[A.children(i)[s]];
    del_tree[i] = del_forest[i] + del[i];
  }
  for (std::uint32_t j = 0; j < n2; ++j) {
    for (std::uint32_t t = 0; t < B.degree(j); ++t) ins_forest[j] += ins_tree[B.children(j)[t]];
    ins_tree[j] = ins_forest[j] + ins[j];
  }
  if (n1 == 0 || n2 == 0) return (n1 ? del_tree[n1 - 1] : 0.0) + (n2 ? ins_tree[n2 - 1] : 0.0);

  std::vector<std::unique_ptr<double[]>> storage;
  std::vector<double*> free_rows;
  const auto take_row = [&]() -> double* {
    if (free_rows.empty()) {
      storage.push_back(std::make_unique<double[]>(n2));
      return storage.back().get();
    }
    double* r = free_rows.back();
    free_rows.pop_back();
    return r;
  };
  std::vector<double*> tree_row(n1, nullptr), forest_row(n1, nullptr);
  std::vector<const double*> child_tree, child_forest;
  std::vector<double> gain, pair_cost, row_alone, col_alone;
  std::vector<int> assign;
  HungarianWorkspace hungarian;
  double result = 0.0;

  for (std::uint32_t i = 0; i < n1; ++i) {
    double* Ti = tree_row[i] = take_row();
    double* Fi = forest_row[i] = take_row();
    const std::uint32_t* ci = A.children(i);
    const std::uint32_t ni = A.degree(i);
    child_tree.resize(ni);
    child_forest.resize(ni);
    for (std::uint32_t s = 0; s < ni; ++s) {
      child_tree[s] = tree_row[ci[s]];
      child_forest[s] = forest_row[ci[s]];
    }
    for (std::uint32_t j = 0; j < n2; ++j) {
      const std::uint32_t* cj = B.children(j);
      const std::uint32_t nj = B.degree(j);
      double f;
      std::uint16_t fcode = kCodeNone;
      if (ni == 0) {
        f = ins_forest[j];
      } else if (nj == 0) {
        f = del_forest[i];
      } else {
        // Restricted mapping: children of i matched one-to-one with children of j.
        const double base = del_forest[i] + ins_forest[j];
        fcode = kCodeMatch;
        if (solver == AssignmentSolver::kMinCostFlow) {
          pair_cost.resize(std::size_t{ni} * nj);
          row_alone.resize(ni);
          col_alone.resize(nj);
          for (std::uint32_t s = 0; s < ni; ++s) {
            row_alone[s] = del_tree[ci[s]];
            for (std::uint32_t t = 0; t < nj; ++t) pair_cost[s * nj + t] = child_tree[s][cj[t]];
          }
          for (std::uint32_t t = 0; t < nj; ++t) col_alone[t] = ins_tree[cj[t]];
          const auto pa = solve_partial_assignment(pair_cost, ni, nj, row_alone, col_alone, solver);
          f = pa.cost;
          if (tb) {
            for (std::uint32_t s = 0; s < ni; ++s) {
              tb->match[std::size_t{ci[s]} * n2 + j] =
                  static_cast<std::uint16_t>(pa.row_to_col[s] + 1);
            }
          }
        } else if (ni == 1 || nj == 1) {
          double best = 0.0;
          std::uint32_t bs = ni, bt = nj;
          for (std::uint32_t s = 0; s < ni; ++s) {
            for (std::uint32_t t = 0; t < nj; ++t) {
              const double g = child_tree[s][cj[t]] - del_tree[ci[s]] - ins_tree[cj[t]];
              if (g <= best) {
                best = g;
                bs = s;
                bt = t;
              }
            }
          }
          f = base + best;
          if (tb) {
            for (std::uint32_t s = 0; s < ni; ++s) {
              tb->match[std::size_t{ci[s]} * n2 + j] =
                  static_cast<std::uint16_t>(s == bs ? bt + 1 : 0);
            }
          }
        } else {
          // Gains (pair cost minus leaving both alone, clamped at 0), smaller side as rows.
          const bool transposed = ni > nj;
          const std::uint32_t rows = transposed ? nj : ni, cols = transposed ? ni : nj;
          gain.resize(std::size_t{rows} * cols);
          assign.resize(rows);
          for (std::uint32_t s = 0; s < ni; ++s) {
            for (std::uint32_t t = 0; t < nj; ++t) {
              const double g =
                  std::min(0.0, child_tree[s][cj[t]] - del_tree[ci[s]] - ins_tree[cj[t]]);
              gain[transposed ? std::size_t{t} * cols + s : std::size_t{s} * cols + t] = g;
            }
          }
          f = base + hungarian.solve(gain.data(), rows, cols, assign.data());
          if (tb) {
            for (std::uint32_t s = 0; s < ni; ++s) tb->match[std::size_t{ci[s]} * n2 + j] = 0;
            for (std::uint32_t r = 0; r < rows; ++r) {
              const std::uint32_t s = transposed ? static_cast<std::uint32_t>(assign[r]) : r;
              const std::uint32_t t = transposed ? r : static_cast<std::uint32_t>(assign[r]);
              if (child_tree[s][cj[t]] <= del_tree[ci[s]] + ins_tree[cj[t]]) {
                tb->match[std::size_t{ci[s]} * n2 + j] = static_cast<std::uint16_t>(t + 1);
              }
            }
          }
        }
        // All of A's forest maps into the forest under one child j_t of j; j_t is inserted.
        for (std::uint32_t t = 0; t < nj; ++t) {
          const double c = ins_forest[j] - ins_forest[cj[t]] + Fi[cj[t]];
          if (c < f) {
            f = c;
            fcode = encode(kCodeInsert, t);
          }
        }
        // Symmetric: all of B's forest maps into the forest under one child i_s of i.
        for (std::uint32_t s = 0; s < ni; ++s) {
          const double c = del_forest[i] - del_forest[ci[s]] + child_forest[s][j];
          if (c < f) {
            f = c;
            fcode = encode(kCodeDelete, s);
          }
        }
      }
      Fi[j] = f;
      // Trees: i relabelled to j with the forests matched, or j inserted with T_A[i] inside
      // one child subtree of j, or i deleted symmetrically.
      double d = f + relabel(i, j);
      std::uint16_t tcode = kCodeMatch;
      for (std::uint32_t t = 0; t < nj; ++t) {
        const double c = ins_tree[j] - ins_tree[cj[t]] + Ti[cj[t]];
        if (c < d) {
          d = c;
          tcode = encode(kCodeInsert, t);
        }
      }
      for (std::uint32_t s = 0; s < ni; ++s) {
        const double c = del_tree[i] - del_tree[ci[s]] + child_tree[s][j];
        if (c < d) {
          d = c;
          tcode = encode(kCodeDelete, s);
        }
      }
      Ti[j] = d;
      if (tb) {
        tb->tree[std::size_t{i} * n2 + j] = tcode;
        tb->forest[std::size_t{i} * n2 + j] = fcode;
      }
    }
    for (std::uint32_t s = 0; s < ni; ++s) {
      free_rows.push_back(tree_row[ci[s]]);
      free_rows.push_back(forest_row[ci[s]]);
      tree_row[ci[s]] = forest_row[ci[s]] = nullptr;
    }
    if (i + 1 == n1) result = Ti[n2 - 1];
  }
  return result;
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
