// Instanced interpretation of substructure graphs against an independent oracle: the explicit
// turtle interpretation of the expanded string (every context-free example at every n whose
// string is small, and grammars built to exercise widths, colours, polygons, homomorphisms and
// brackets that close outside their substructure); closed forms for the memo at large n.
#include "lsystem/instanced_interpretation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_ctree.hpp"
#include "lsystem/parser.hpp"

namespace fspm::lsystem {
namespace {

std::string example(const std::string& name) {
  return std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/" + name;
}

// One drawn node, as the explicit interpretation's tree holds it.
struct Drawn {
  OrganKind kind;
  Eigen::Vector3d start, end;
  double length, radius, color, leaf_area;
  int order;
};

std::vector<Drawn> drawn_nodes(const TreeGraph& t) {
  std::vector<Drawn> out;
  const bool leaves = t.has_attribute("leaf_area");
  for (NodeId n = 0; n < t.size(); ++n) {
    out.push_back({t.kind(n), t.start(n), t.end(n), t.length(n), t.radius(n),
                   t.attribute("color_index")[n], leaves ? t.attribute("leaf_area")[n] : 0.0,
                   t.order(n)});
  }
  return out;
}

// Both lists in one order: by kind, then by start and end rounded to a grid far coarser than the
// rounding differences of composed transforms, far finer than the drawing.
void sort_nodes(std::vector<Drawn>& v, double grid) {
  const auto key = [grid](const Drawn& d) {
    return std::make_tuple(static_cast<int>(d.kind), std::llround(d.start.x() / grid),
                           std::llround(d.start.y() / grid), std::llround(d.start.z() / grid),
                           std::llround(d.end.x() / grid), std::llround(d.end.y() / grid),
                           std::llround(d.end.z() / grid), d.color, d.order);
  };
  std::sort(v.begin(), v.end(), [&](const Drawn& a, const Drawn& b) { return key(a) < key(b); });
}

double extent(const TreeGraph& t) {
  Eigen::AlignedBox3d box;
  for (NodeId n = 0; n < t.size(); ++n) {
    box.extend(t.start(n));
    box.extend(t.end(n));
  }
  return box.isEmpty() ? 1.0 : std::max(box.sizes().maxCoeff(), 1e-300);
}

// `flat` and `reference` hold the same nodes up to numbering: kinds, segments within 1e-9 of the
// plant's extent, lengths, radii, colours, orders and leaf areas.
void expect_same_nodes(const TreeGraph& flat, const TreeGraph& reference, const std::string& what) {
  ASSERT_EQ(flat.size(), reference.size()) << what;
  if (flat.empty()) return;
  const double tol = 1e-9 * extent(reference);
  std::vector<Drawn> a = drawn_nodes(flat), b = drawn_nodes(reference);
  sort_nodes(a, 1e-6 * extent(reference));
  sort_nodes(b, 1e-6 * extent(reference));
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].kind, b[i].kind) << what << " node " << i;
    ASSERT_LE((a[i].start - b[i].start).norm(), tol) << what << " node " << i;
    ASSERT_LE((a[i].end - b[i].end).norm(), tol) << what << " node " << i;
    ASSERT_NEAR(a[i].length, b[i].length, tol) << what;
    ASSERT_NEAR(a[i].radius, b[i].radius, 1e-9 * std::max(1.0, std::abs(b[i].radius))) << what;
    ASSERT_EQ(a[i].color, b[i].color) << what;
    ASSERT_EQ(a[i].order, b[i].order) << what;
    ASSERT_NEAR(a[i].leaf_area, b[i].leaf_area, 1e-9 * std::max(1.0, b[i].leaf_area)) << what;
  }
}

// The instanced interpretation of `sys` after `n` steps, flattened, equals the explicit one node
// for node within 1e-9 of the plant's extent.
void expect_same_drawing(const LSystem& sys, int n, const TurtleSettings& view,
                         const std::string& what) {
  DeriveOptions options;
  options.steps = n;
  const SubstructureGraph g = derive_substructures(sys, options);
  const InstancedInterpretation inst = interpret_instanced(g, sys, view);
  EXPECT_EQ(inst.explicit_reason, "") << what;
  Derivation d(sys, options);
  d.run();
  const Interpretation reference = interpret(d.interpretation_string(), sys.symbols, view);
  const TreeGraph flat = expand_instanced_tree(inst.tree, 10'000'000);
  ASSERT_EQ(flat.size(), reference.tree.size()) << what;
  std::uint64_t internodes = 0, leaves = 0;
  for (const OrganKind k : reference.tree.kinds()) {
    internodes += k == OrganKind::kInternode ? 1 : 0;
    leaves += k == OrganKind::kLeaf ? 1 : 0;
  }
  EXPECT_EQ(inst.internodes, internodes) << what;
  EXPECT_EQ(inst.leaves, leaves) << what;
  if (flat.empty()) return;
  const double tol = 1e-9 * extent(reference.tree);
  std::vector<Drawn> a = drawn_nodes(flat), b = drawn_nodes(reference.tree);
  sort_nodes(a, 1e-6 * extent(reference.tree));
  sort_nodes(b, 1e-6 * extent(reference.tree));
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].kind, b[i].kind) << what << " node " << i;
    ASSERT_LE((a[i].start - b[i].start).norm(), tol) << what << " node " << i;
    ASSERT_LE((a[i].end - b[i].end).norm(), tol) << what << " node " << i;
    ASSERT_NEAR(a[i].length, b[i].length, tol) << what;
    ASSERT_NEAR(a[i].radius, b[i].radius, 1e-9 * std::max(1.0, std::abs(b[i].radius))) << what;
    ASSERT_EQ(a[i].color, b[i].color) << what;
    ASSERT_EQ(a[i].order, b[i].order) << what;
    ASSERT_NEAR(a[i].leaf_area, b[i].leaf_area, 1e-9 * std::max(1.0, b[i].leaf_area)) << what;
  }
}

TEST(InstancedInterpretation, EveryFactorizableExampleDrawsAsItsExplicitString) {
  constexpr std::size_t kSmall = 200'000;  // explicit strings drawn up to this size
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(example(""))) {
    if (entry.path().extension() != ".l") continue;
    const LSystem sys = parse_lsystem_file(entry.path().string());
    if (factorization_obstacle(sys)) continue;
    const TurtleSettings view = view_for_lsystem(entry.path().string());
    for (int n = 0; n <= 30; ++n) {
      DeriveOptions options;
      options.steps = n;
      options.module_budget = kSmall;
      try {
        (void)derive(sys, options);
      } catch (const ValueError&) {
        break;  // past kSmall modules
      }
      const InstancedInterpretation probe =
          interpret_instanced(derive_substructures(sys, options), sys, view);
      if (!probe.explicit_reason.empty()) break;  // $ or tropism: drawn explicitly
      expect_same_drawing(sys, n, view,
                          entry.path().filename().string() + " n=" + std::to_string(n));
      ++compared;
    }
  }
  // Figures 1.24a-f, the parametric tree, the leafy shoot and the GreenLab grammar.
  EXPECT_GE(compared, 50);
}

// The .ctree written from the instanced interpretation (fspm/instanced_ctree.hpp), encoded and
// decoded, expands to the explicit turtle's tree: the explicit interpretation of the expanded
// string is an independent implementation of the drawing.
void expect_same_ctree(const LSystem& sys, int n, const TurtleSettings& view,
                       const std::string& what) {
  DeriveOptions options;
  options.steps = n;
  const InstancedInterpretation inst =
      interpret_instanced(derive_substructures(sys, options), sys, view);
  const CompressedTreeGraph written = compress_instanced_tree(inst.tree);
  const CompressedTreeGraph read = decode_ctree(encode_ctree(written), what);
  EXPECT_TRUE(read == written) << what;
  Derivation d(sys, options);
  d.run();
  const Interpretation reference = interpret(d.interpretation_string(), sys.symbols, view);
  EXPECT_EQ(geometry_organ_count(read), reference.tree.size()) << what;
  expect_same_nodes(expand_instanced_tree(instanced_tree_of(read), 10'000'000), reference.tree,
                    what);
}

TEST(InstancedInterpretation, CtreeOfEveryFactorizableExampleExpandsToTheExplicitTree) {
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(example(""))) {
    if (entry.path().extension() != ".l") continue;
    const LSystem sys = parse_lsystem_file(entry.path().string());
    if (factorization_obstacle(sys)) continue;
    const TurtleSettings view = view_for_lsystem(entry.path().string());
    for (int n = 0; n <= 30; ++n) {
      DeriveOptions options;
      options.steps = n;
      options.module_budget = 50'000;
      try {
        (void)derive(sys, options);
      } catch (const ValueError&) {
        break;
      }
      expect_same_ctree(sys, n, view, entry.path().filename().string() + " n=" + std::to_string(n));
      ++compared;
    }
  }
  EXPECT_GE(compared, 40);
}

// Fig. 1.24a at n = 20 as a .ctree: a group per prototype (the axiom and F(k), k = 1..20) and the
// five internodes F(1) draws: 26 records for 5^20 internodes, counted by the multiplicities
// without expanding (the five records of F(1) stand for 5^19 internodes each).
TEST(InstancedInterpretation, CtreeOfFigure124aAtTwentyStepsCountsWithoutExpanding) {
  const LSystem sys = parse_lsystem_file(example("abop_1_24a.l"));
  DeriveOptions options;
  options.steps = 20;
  const InstancedInterpretation inst = interpret_instanced(
      derive_substructures(sys, options), sys, view_for_lsystem(example("abop_1_24a.l")));
  const CompressedTreeGraph g = decode_ctree(encode_ctree(compress_instanced_tree(inst.tree)));
  EXPECT_EQ(g.size(), 21u + 5u);
  std::uint64_t five_n = 1;
  for (int k = 0; k < 20; ++k) five_n *= 5;
  EXPECT_EQ(geometry_organ_count(g), five_n);
  EXPECT_LT(encode_ctree(g).size(), 20'000u);
}

TEST(InstancedInterpretation, WidthsColoursPolygonsAndOpenBracketsDrawAsExplicitly) {
  TurtleSettings view;
  view.angle_deg = 30.0;
  view.line_width_unit = LineWidthUnit::kModel;
  // Width and colour change inside substructures and differ where they start.
  const LSystem widths = parse_lsystem("Axiom: A\nA --> F;[+A]!(0.5)F[-A];(2)A\n", "w.l");
  // Polygons drawn by a homomorphism of a leaf module, with a colour.
  const LSystem polygons = parse_lsystem(
      "Axiom: A\nA --> F[&L]/(90)A\nhomomorphism\nL --> ;{.-f.+(60)f.+(120)f.}\n", "p.l");
  // B opens a polygon that C closes: both walked through, not instanced (the last B is left open,
  // so what follows it in its branch are polygon vertices); A is self-contained.
  const LSystem open =
      parse_lsystem("Axiom: A\nA --> F[+B]A\nB --> {.-f.C\nC --> +f.-f.}F\n", "o.l");
  for (int n = 0; n <= 6; ++n) {
    expect_same_drawing(widths, n, view, "widths n=" + std::to_string(n));
    expect_same_drawing(polygons, n, view, "polygons n=" + std::to_string(n));
    expect_same_drawing(open, n, view, "open n=" + std::to_string(n));
    expect_same_ctree(widths, n, view, "widths ctree n=" + std::to_string(n));
    expect_same_ctree(polygons, n, view, "polygons ctree n=" + std::to_string(n));
    expect_same_ctree(open, n, view, "open ctree n=" + std::to_string(n));
  }
}

// Fig. 1.24a: F(k) for k = 1..n remaining steps are the prototypes (F(0) is drawn inside F(1)),
// with the axiom's: n + 1, however large the plant. Each F(k), k > 1, places five F(k - 1), so
// the F(1) occur 5^(n-1) times and draw 5^n internodes.
TEST(InstancedInterpretation, Figure124aAtTwentyStepsHasOnePrototypePerLevel) {
  const LSystem sys = parse_lsystem_file(example("abop_1_24a.l"));
  DeriveOptions options;
  options.steps = 20;
  const InstancedInterpretation inst = interpret_instanced(
      derive_substructures(sys, options), sys, view_for_lsystem(example("abop_1_24a.l")));
  EXPECT_EQ(inst.tree.prototypes.size(), 21u);
  std::uint64_t five_n = 1;
  for (int k = 0; k < 20; ++k) five_n *= 5;
  EXPECT_EQ(inst.internodes, five_n);
  EXPECT_EQ(inst.instances, five_n / 5);
  for (std::size_t p = 1; p + 1 < inst.tree.prototypes.size(); ++p) {
    EXPECT_EQ(inst.tree.prototypes[p].children.size(), 5u);
  }
  // The main axis of F(20) is 3^20 steps straight up: its pixel width (2 of 500 pixels) makes
  // the internodes' radius 3^20 / 500 at least (the box is as wide as high or less).
  const TreeGraph& f1 = inst.tree.prototypes.back().geometry;
  ASSERT_EQ(f1.size(), 5u);
  EXPECT_GE(f1.radius(0), std::pow(3.0, 20) / 500.0 * (1.0 - 1e-12));
}

TEST(InstancedInterpretation, LevelOfDetailDrawsSmallSubstructuresAsTheirChord) {
  const LSystem sys = parse_lsystem_file(example("abop_1_24a.l"));
  DeriveOptions options;
  options.steps = 3;
  TurtleSettings view;
  view.angle_deg = 25.7;
  InstancedInterpretationOptions lod;
  lod.min_detail = 1e9;  // everything is small: F(3) is one internode up its main axis
  const InstancedInterpretation inst =
      interpret_instanced(derive_substructures(sys, options), sys, view, lod);
  const TreeGraph flat = expand_instanced_tree(inst.tree, 1000);
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_NEAR((flat.end(0) - Eigen::Vector3d(0, 0, 27)).norm(), 0.0, 1e-12);
}

TEST(InstancedInterpretation, TropismAndRollToHorizontalFallBackToExplicit) {
  const LSystem roll = parse_lsystem("Axiom: A\nA --> F[+$A]A\n", "r.l");
  DeriveOptions options;
  options.steps = 4;
  const InstancedInterpretation r =
      interpret_instanced(derive_substructures(roll, options), roll, TurtleSettings{});
  EXPECT_NE(r.explicit_reason.find("$"), std::string::npos);
  EXPECT_EQ(r.tree.prototypes.size(), 1u);
  EXPECT_EQ(r.internodes, 15u);  // 2^4 - 1
  const LSystem plain = parse_lsystem("Axiom: A\nA --> F[+A]A\n", "t.l");
  TurtleSettings bent;
  bent.initial_elasticity = 0.2;
  const InstancedInterpretation t =
      interpret_instanced(derive_substructures(plain, options), plain, bent);
  EXPECT_NE(t.explicit_reason.find("tropism"), std::string::npos);
  EXPECT_EQ(t.internodes, 15u);
}

// Jaeger's stochastic case: every substructure of the stochastic Fig. 1.27 in at most K variants.
// The same seed gives the same graph; every (module, remaining steps) has at most K variants; the
// drawing by instancing is the explicit drawing of the graph's string.
TEST(InstancedInterpretation, StochasticVariantsAreDeterministicAndBounded) {
  const LSystem sys = parse_lsystem_file(example("stochastic_plant.l"));
  EXPECT_TRUE(factorization_obstacle(sys).has_value());
  EXPECT_FALSE(factorization_obstacle(sys, true).has_value());
  DeriveOptions options;
  options.steps = 8;
  options.seed = 11;
  const SubstructureGraph a = derive_substructures(sys, options, 3);
  const SubstructureGraph b = derive_substructures(sys, options, 3);
  EXPECT_EQ(a.children, b.children);
  EXPECT_EQ(a.axiom, b.axiom);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  std::map<std::pair<SymbolId, int>, int> per_class;
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].symbol, b.nodes[i].symbol);
    EXPECT_EQ(a.nodes[i].remaining, b.nodes[i].remaining);
    ++per_class[{a.nodes[i].symbol, a.nodes[i].remaining}];
  }
  for (const auto& [cls, count] : per_class) EXPECT_LE(count, 3);
  // F after 1..8 remaining steps: more than one variant somewhere (three productions).
  EXPECT_GT(a.nodes.size(), 8u + 4u + 1u);
  options.seed = 12;
  const SubstructureGraph c = derive_substructures(sys, options, 3);
  EXPECT_TRUE(c.children != a.children || c.axiom != a.axiom);
  // One variant each: as many substructures as the deterministic Fig. 1.24a's at most.
  EXPECT_LE(derive_substructures(sys, options, 1).nodes.size(), 8u + 1u + 4u);
  const TurtleSettings view = view_for_lsystem(example("stochastic_plant.l"));
  options.steps = 5;
  const SubstructureGraph g = derive_substructures(sys, options, 2);
  const Interpretation reference = interpret(expand(g, 1'000'000), sys.symbols, view);
  const TreeGraph flat = expand_instanced_tree(interpret_instanced(g, sys, view).tree, 1'000'000);
  ASSERT_EQ(flat.size(), reference.tree.size());
  std::vector<Drawn> x = drawn_nodes(flat), y = drawn_nodes(reference.tree);
  const double size = extent(reference.tree);
  sort_nodes(x, 1e-6 * size);
  sort_nodes(y, 1e-6 * size);
  for (std::size_t i = 0; i < x.size(); ++i) {
    ASSERT_LE((x[i].start - y[i].start).norm(), 1e-9 * size);
    ASSERT_LE((x[i].end - y[i].end).norm(), 1e-9 * size);
    ASSERT_NEAR(x[i].radius, y[i].radius, 1e-9 * y[i].radius);
  }
}

}  // namespace
}  // namespace fspm::lsystem
