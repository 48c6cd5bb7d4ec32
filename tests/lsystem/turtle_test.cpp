#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fspm/error.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/open_environment.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/turtle.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm::lsystem {
namespace {

Interpretation draw(const std::string& axiom, TurtleSettings settings = {}) {
  const LSystem sys = parse_lsystem("Axiom: " + axiom + "\n");
  return interpret(derive(sys), sys.symbols, settings);
}

TEST(LsystemTurtle, ForwardAndTurns) {
  const Interpretation r = draw("F+F");
  ASSERT_EQ(r.tree.size(), 2u);
  EXPECT_TRUE(r.tree.end(0).isApprox(Eigen::Vector3d(0, 0, 1)));
  // + turns toward L = -x.
  EXPECT_TRUE(r.tree.end(1).isApprox(Eigen::Vector3d(-1, 0, 1)));
  EXPECT_EQ(r.tree.parent(1), 0u);
  EXPECT_NEAR(r.tree.length(1), 1.0, 1e-12);
}

TEST(LsystemTurtle, AllRotationsKeepAnOrthonormalFrame) {
  // Pitch down then forward: & turns H toward -U = +y.
  const Interpretation r = draw("F&F");
  EXPECT_TRUE(r.tree.end(1).isApprox(Eigen::Vector3d(0, 1, 1)));
  // | turns around.
  const Interpretation back = draw("F|F");
  EXPECT_TRUE(back.tree.end(1).isApprox(Eigen::Vector3d(0, 0, 0)) ||
              back.tree.end(1).norm() < 1e-12);
  // \ and / roll about H: a roll then a turn changes the turn's plane.
  const Interpretation roll = draw("F\\(90)+F");
  EXPECT_NEAR(std::abs(roll.tree.end(1).y()), 1.0, 1e-12);
  EXPECT_NEAR(roll.tree.end(1).x(), 0.0, 1e-12);
  // Parametric angles and lengths.
  const Interpretation p = draw("F(2)-(45)F(1)");
  EXPECT_NEAR(p.tree.end(1).x(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(p.tree.end(1).z(), 2 + std::sqrt(0.5), 1e-12);
}

TEST(LsystemTurtle, BranchesSetParentsAndOrders) {
  const Interpretation r = draw("F[+F[-F]]F");
  ASSERT_EQ(r.tree.size(), 4u);
  EXPECT_EQ(r.tree.order(0), 0);
  EXPECT_EQ(r.tree.order(1), 1);
  EXPECT_EQ(r.tree.order(2), 2);
  EXPECT_EQ(r.tree.order(3), 0);
  EXPECT_EQ(r.tree.parent(1), 0u);
  EXPECT_EQ(r.tree.parent(2), 1u);
  EXPECT_EQ(r.tree.parent(3), 0u);
  EXPECT_TRUE(r.tree.start(3).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_THROW(draw("F]F"), ParseError);  // refused by the parser, at its line and column
}

TEST(LsystemTurtle, MoveWithoutDrawingLeavesAGap) {
  const Interpretation r = draw("FfF");
  ASSERT_EQ(r.tree.size(), 2u);
  EXPECT_TRUE(r.tree.start(1).isApprox(Eigen::Vector3d(0, 0, 2)));
  EXPECT_EQ(r.tree.parent(1), 0u);
}

TEST(LsystemTurtle, LineWidthGivesRadius) {
  TurtleSettings s;
  s.line_width_unit = LineWidthUnit::kModel;  // the width is a diameter in model units
  s.initial_line_width = 4;
  s.line_width_increment = 1;
  const Interpretation r = draw("F!F!(1)F#F", s);
  EXPECT_DOUBLE_EQ(r.tree.radius(0), 2.0);
  EXPECT_DOUBLE_EQ(r.tree.radius(1), 1.5);
  EXPECT_DOUBLE_EQ(r.tree.radius(2), 0.5);
  EXPECT_DOUBLE_EQ(r.tree.radius(3), 1.0);
}

TEST(LsystemTurtle, PixelWidthsScaleWithThePlant) {
  // cpfg's default line style: widths in pixels of a picture kPixelsAcrossPlant wide. A 10-unit
  // stem (extent 10) of width 5 px: diameter 5 * 10 / 500 = 0.1, radius 0.05.
  const Interpretation r = draw("!(5)F(4)F(6)");
  ASSERT_EQ(r.tree.size(), 2u);
  EXPECT_NEAR(r.tree.radius(0), 0.5 * 5.0 * 10.0 / kPixelsAcrossPlant, 1e-12);
  EXPECT_NEAR(r.tree.radius(1), r.tree.radius(0), 1e-12);
  // Twice the plant, twice the radius: the picture keeps its proportions.
  const Interpretation big = draw("!(5)F(8)F(12)");
  EXPECT_NEAR(big.tree.radius(0), 2.0 * r.tree.radius(0), 1e-12);
  // The extent is the largest side of the box: a 3 x 4 L spans 4.
  const Interpretation l = draw("!(2)F(4)+F(3)");
  EXPECT_NEAR(l.tree.radius(1), 0.5 * 2.0 * 4.0 / kPixelsAcrossPlant, 1e-12);
  // A sphere without a diameter takes the line width in pixels; with one, model units.
  const Interpretation o = draw("!(10)F(5)@o@o(2)");
  EXPECT_NEAR(o.tree.radius(1), 0.5 * 10.0 * 5.0 / kPixelsAcrossPlant, 1e-12);
  EXPECT_NEAR(o.tree.radius(2), 1.0, 1e-12);
}

TEST(LsystemTurtle, PolygonsBecomeLeavesWithTheirArea) {
  const Interpretation r = draw("F[{.f+f+f+f}]");
  ASSERT_EQ(r.leaves.size(), 1u);
  EXPECT_NEAR(r.leaves[0].area, 1.0, 1e-12);
  EXPECT_EQ(r.leaves[0].vertices.size(), 4u);
  ASSERT_EQ(r.tree.size(), 2u);
  EXPECT_EQ(r.tree.kind(1), OrganKind::kLeaf);
  EXPECT_EQ(r.tree.parent(1), 0u);
  EXPECT_NEAR(r.tree.attribute("leaf_area")[1], 1.0, 1e-12);
  // A triangle with G moves (no vertex) and explicit dots: legs 2 and 1 -> area 1.
  const Interpretation t = draw("F{.G(2).+G(1).}");
  ASSERT_EQ(t.leaves.size(), 1u);
  EXPECT_NEAR(t.leaves[0].area, 1.0, 1e-12);
  EXPECT_THROW(draw("F}"), ValueError);
}

TEST(LsystemTurtle, SpheresAreFlowers) {
  const Interpretation r = draw("F(2)@o(0.5)");
  ASSERT_EQ(r.tree.size(), 2u);
  EXPECT_EQ(r.tree.kind(1), OrganKind::kFlower);
  EXPECT_DOUBLE_EQ(r.tree.radius(1), 0.25);
  EXPECT_TRUE(r.tree.start(1).isApprox(Eigen::Vector3d(0, 0, 2)));
  EXPECT_EQ(r.tree.parent(1), 0u);
}

TEST(LsystemTurtle, TropismBendsTowardTheDirection) {
  TurtleSettings s;
  s.initial_elasticity = 0.2;
  s.tropism_direction = Eigen::Vector3d(0, 0, -1);
  const Interpretation r = draw("+(90)FF", s);
  // After the first F the heading turns by e |H x T| = 0.2 rad toward -z.
  EXPECT_NEAR(r.tree.direction(1).z(), -std::sin(0.2), 1e-12);
  EXPECT_NEAR(r.tree.direction(0).z(), 0.0, 1e-12);
  // A vertical heading along T is not bent.
  const Interpretation v = draw("FF", s);
  EXPECT_NEAR(v.tree.direction(1).z(), 1.0, 1e-12);
}

TEST(LsystemTurtle, ViewFileKeys) {
  const TurtleSettings s = parse_view(
      "Angle Factor: 8\ninitial line width: 3 pixels\nline width increment: 0.5\n"
      "tropism direction: 0,-1,0\ninitial elasticity: 0.1\nelasticity increment: 0.05\n"
      "projection: parallel\n");
  EXPECT_DOUBLE_EQ(s.angle_deg, 45.0);
  EXPECT_DOUBLE_EQ(s.initial_line_width, 3.0);
  EXPECT_EQ(s.line_width_unit, LineWidthUnit::kPixel);
  EXPECT_DOUBLE_EQ(s.line_width_increment, 0.5);
  // cpfg: a width without a unit is in model units; `line style` decides when given after it.
  EXPECT_EQ(parse_view("initial line width: 0.1\n").line_width_unit, LineWidthUnit::kModel);
  EXPECT_EQ(parse_view("initial line width: 2 p\n").line_width_unit, LineWidthUnit::kPixel);
  EXPECT_EQ(parse_view("angle increment: 30\n").line_width_unit, LineWidthUnit::kPixel);
  EXPECT_EQ(parse_view("initial line width: 2 pixels\nline style: cylinder\n").line_width_unit,
            LineWidthUnit::kModel);
  EXPECT_EQ(parse_view("initial line width: 2\nLine Style: pixel\n").line_width_unit,
            LineWidthUnit::kPixel);
  EXPECT_THROW(parse_view("line style: thick\n"), ParseError);
  EXPECT_TRUE(s.tropism_direction.isApprox(Eigen::Vector3d(0, 0, -1)));  // cpfg y-up
  EXPECT_DOUBLE_EQ(s.initial_elasticity, 0.1);
  EXPECT_DOUBLE_EQ(s.elasticity_increment, 0.05);
  EXPECT_DOUBLE_EQ(parse_view("angle increment: 25.7\n").angle_deg, 25.7);
  EXPECT_THROW(parse_view("angle factor: x\n"), ParseError);
}

TEST(LsystemTurtle, QueryModulesGetTheTurtleState) {
  const LSystem sys = parse_lsystem("Axiom: F(2)+(90)F(1)?P(0,0,0)?H(0,0,0)?L(0,0,0)?U(0,0,0)\n");
  const ModuleString s = derive(sys);
  auto param = [&](int module) { return s.parameters(static_cast<std::size_t>(module)); };
  // Modules: F + F ?P ?H ?L ?U
  EXPECT_NEAR(param(3)[0], -1.0, 1e-12);
  EXPECT_NEAR(param(3)[2], 2.0, 1e-12);
  EXPECT_NEAR(param(4)[0], -1.0, 1e-12);  // heading -x
  EXPECT_NEAR(param(5)[2], -1.0, 1e-12);  // left turned to -z
  EXPECT_NEAR(param(6)[1], -1.0, 1e-12);  // up stays -y
}

TEST(LsystemTurtle, QueryPassDrawsTheHomomorphism) {
  // A draws nothing in the derived string but F(3) through the homomorphism.
  const LSystem sys = parse_lsystem("Axiom: A?P(0,0,0)\nhomomorphism\nA --> F(3)\n");
  const ModuleString s = derive(sys);
  EXPECT_NEAR(s.parameters(1)[2], 3.0, 1e-12);
  EXPECT_EQ(sys.symbols.name(s.symbol(0)), "A");
}

class HeightEnvironment : public OpenEnvironment {
 public:
  void respond(std::span<EnvironmentQuery> queries) override {
    ++calls;
    for (auto& q : queries) q.parameters = {q.position.z(), 42.0};
  }
  int calls = 0;
};

TEST(LsystemTurtle, CommunicationModulesAskTheEnvironment) {
  const LSystem sys = parse_lsystem("Axiom: A?E(0)\nA --> F(1)A\n?E(h,k) : h > 1.5 --> X(h,k)\n");
  HeightEnvironment env;
  DeriveOptions o;
  o.steps = 3;
  o.environment = &env;
  const ModuleString s = derive(sys, o);
  EXPECT_EQ(env.calls, 3);  // axiom, steps 1 and 2 (no ?E left after step 3)
  // After step 2 the ?E sits at height 2 and the production with h > 1.5 fires in step 3.
  EXPECT_EQ(to_string(s, sys.symbols), "F(1)F(1)F(1)AX(2,42)");
}

TEST(LsystemTurtle, Abop124aGeometry) {
  const std::string path = std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/abop_1_24a.l";
  const LSystem sys = parse_lsystem_file(path);
  const TurtleSettings view = view_for_lsystem(path);
  EXPECT_DOUBLE_EQ(view.angle_deg, 25.7);
  // n = 1: F[+F]F[-F]F by hand.
  DeriveOptions one;
  one.steps = 1;
  const Interpretation r = interpret(derive(sys, one), sys.symbols, view);
  ASSERT_EQ(r.tree.size(), 5u);
  const double s = std::sin(25.7 * std::numbers::pi / 180);
  const double c = std::cos(25.7 * std::numbers::pi / 180);
  EXPECT_TRUE(r.tree.end(1).isApprox(Eigen::Vector3d(-s, 0, 1 + c)));
  EXPECT_TRUE(r.tree.end(3).isApprox(Eigen::Vector3d(s, 0, 2 + c)));
  EXPECT_TRUE(r.tree.end(4).isApprox(Eigen::Vector3d(0, 0, 3)));
  EXPECT_EQ(r.tree.parent(3), 2u);
  EXPECT_EQ(r.tree.parent(4), 2u);
  // n = 5: the trunk keeps 3 of the 5 F of every trunk F: 3^5 = 243 order-0 internodes, and
  // 5^5 internodes in all.
  const Interpretation big = interpret(derive(sys), sys.symbols, view);
  EXPECT_EQ(big.tree.size(), 3125u);
  int trunk = 0;
  double top = 0;
  for (NodeId n = 0; n < big.tree.size(); ++n) {
    if (big.tree.order(n) != 0) continue;
    ++trunk;
    top = std::max(top, big.tree.end(n).z());
  }
  EXPECT_EQ(trunk, 243);
  EXPECT_NEAR(top, 243.0, 1e-9);
  // Initial line width 2 pixels of a picture kPixelsAcrossPlant across the plant's height 243.
  EXPECT_EQ(view.line_width_unit, LineWidthUnit::kPixel);
  EXPECT_NEAR(big.tree.radius(0), 0.5 * 2.0 * 243.0 / kPixelsAcrossPlant, 1e-9);
}

TEST(LsystemTurtle, LeafyShootLeavesAreRhombi) {
  const std::string path = std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/leafy_shoot.l";
  const LSystem sys = parse_lsystem_file(path);
  const Interpretation r = interpret(derive(sys), sys.symbols, view_for_lsystem(path));
  ASSERT_EQ(r.leaves.size(), 12u);
  const double area = 0.16 * std::sin(50.0 * std::numbers::pi / 180);
  for (const LeafPolygon& leaf : r.leaves) {
    EXPECT_NEAR(leaf.area, area, 1e-12);
    EXPECT_EQ(leaf.vertices.size(), 4u);
    EXPECT_EQ(r.tree.kind(leaf.node), OrganKind::kLeaf);
    EXPECT_EQ(r.tree.order(leaf.node), 1);
    EXPECT_EQ(r.tree.kind(r.tree.parent(leaf.node)), OrganKind::kInternode);
  }
  EXPECT_EQ(r.tree.size(), 24u);
}

TEST(LsystemTurtle, ExamplesDrawTrees) {
  const std::string dir = std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/";
  for (const char* name : {"abop_1_24a", "parametric_tree", "monopodial_tree", "greenlab",
                           "leafy_shoot", "context_sensitive_plant", "stochastic_plant"}) {
    const std::string path = dir + name + ".l";
    const LSystem sys = parse_lsystem_file(path);
    Derivation d(sys);
    d.run();
    const Interpretation r =
        interpret(d.interpretation_string(), sys.symbols, view_for_lsystem(path));
    EXPECT_GT(r.tree.size(), 10u) << name;
    for (NodeId n = 1; n < r.tree.size(); ++n) ASSERT_LT(r.tree.parent(n), n);
  }
}

// The tree of an interpretation is checked before it is allocated: 141 bytes per drawn module
// (a node with two attributes and its colour), so at 1 MiB 4 096 F modules (577 kB) are drawn
// and 8 192 (1.15 MB) stop with MemoryLimitError, although their string is only 16 kB.
TEST(Turtle, MemoryLimitStopsTheTreeInBytes) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  const LSystem sys = parse_lsystem("Axiom: F\nF --> FF\n", "double.l");
  DeriveOptions o;
  o.steps = 12;
  EXPECT_EQ(interpret(derive(sys, o), sys.symbols, {}).tree.size(), 4096u);
  o.steps = 13;
  const ModuleString s = derive(sys, o);
  EXPECT_THROW(interpret(s, sys.symbols, {}), MemoryLimitError);
}

}  // namespace
}  // namespace fspm::lsystem
