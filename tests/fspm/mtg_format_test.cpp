#include "fspm/mtg_format.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <sstream>

#include "fspm/error.hpp"
#include "tests/fspm/random_tree.hpp"

namespace fspm {
namespace {

// Export then import: the same tree up to node numbering (the file lists nodes depth first).
// Nodes are matched by their end points, which are distinct in a random tree.
TEST(MtgRead, ExportedTreesComeBackUpToNodeNumbering) {
  std::mt19937_64 rng(7);
  for (int rep = 0; rep < 20; ++rep) {
    const TreeGraph t = testing::random_tree(rng, 1 + rep * 11, rep % 3);
    std::ostringstream out;
    write_mtg(t, out);
    const TreeGraph back = parse_mtg(out.str(), "mem.mtg");
    ASSERT_EQ(back.size(), t.size()) << rep;
    std::map<std::array<double, 3>, NodeId> by_end;
    for (NodeId n = 0; n < t.size(); ++n) by_end[{t.end(n).x(), t.end(n).y(), t.end(n).z()}] = n;
    std::vector<NodeId> original(back.size());
    for (NodeId m = 0; m < back.size(); ++m) {
      const auto it = by_end.find({back.end(m).x(), back.end(m).y(), back.end(m).z()});
      ASSERT_NE(it, by_end.end()) << "rep " << rep << " node " << m;
      original[m] = it->second;
    }
    for (NodeId m = 0; m < back.size(); ++m) {
      const NodeId n = original[m];
      EXPECT_EQ(back.parent(m) == kNoNode ? kNoNode : original[back.parent(m)], t.parent(n));
      EXPECT_EQ(back.kind(m), t.kind(n));
      EXPECT_EQ(back.length(m), t.length(n));
      EXPECT_EQ(back.radius(m), t.radius(n));
      EXPECT_EQ(back.birth_time(m), t.birth_time(n));
      EXPECT_EQ(back.order(m), t.order(n));
      if (m > 0 && t.length(n) != 0.0) {
        EXPECT_EQ(back.start(m), back.end(back.parent(m)));
      }
      for (const std::string& a : t.attribute_names()) {
        const double want = t.attribute(a)[n];
        const double got = back.attribute(a)[m];
        EXPECT_TRUE(std::isnan(want) ? std::isnan(got) : got == want) << a;
      }
    }
  }
}

// A plant of two growth units U1 < U2, decomposed into internodes E (three scales). E2 bears a
// branch E3 carrying E4; U2's first internode E5 follows U1's last internode on the axis, E2,
// not the branch; "^<U2" refers to U1 (the last entity of U's scale in the column), and the
// branch unit U3 borne by U1 starts at its last axis internode too.
constexpr const char* kMultiscale =
    "CODE:\tFORM-A\n"
    "CLASSES:\n"
    "SYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION\n"
    "$\t0\tFREE\tFREE\tIMPLICIT\n"
    "P\t1\tCONNECTED\tFREE\tIMPLICIT\n"
    "U\t2\tCONNECTED\tFREE\tIMPLICIT\n"
    "E\t3\tNONE\tFREE\tIMPLICIT\n"
    "\n"
    "FEATURES:\n"
    "NAME\tTYPE\n"
    "Length\tREAL\n"
    "Diameter\tREAL\n"
    "Date\tDD/MM/YY\n"
    "\n"
    "MTG:\n"
    "ENTITY-CODE\t\t\tLength\tDiameter\tDate\n"
    "/P1/U1/E1\t\t\t10\t2\t01/03/98\n"
    "^<E2\t\t\t8\t1.8\t\n"
    "\t+E3\t\t5\t1\t\n"
    "\t^<E4\t\t4\t0.8\t\n"
    "^<U2/E5\t\t\t6\t1.5\t  # a comment\n"
    "\t+U3/E6\t\t3\t0.5\t\n";

TEST(MtgRead, FinestScaleOfAMultiscaleFile) {
  const TreeGraph t = parse_mtg(kMultiscale, "plant.mtg");
  ASSERT_EQ(t.size(), 6u);
  // File order: E1 E2 E3 E4 E5 E6 -> ids 0..5.
  EXPECT_EQ(t.parent(0), kNoNode);
  EXPECT_EQ(t.parent(1), 0u);
  EXPECT_EQ(t.parent(2), 1u);  // +E3 on E2
  EXPECT_EQ(t.parent(3), 2u);  // E4 after E3
  EXPECT_EQ(t.parent(4), 1u);  // E5 (first of U2) after E2, the last internode of U1's axis
  EXPECT_EQ(t.parent(5), 4u);  // E6 (first of U3, borne by U2) on U2's last internode, E5
  EXPECT_EQ(t.order(0), 0);
  EXPECT_EQ(t.order(2), 1);
  EXPECT_EQ(t.order(3), 1);
  EXPECT_EQ(t.order(4), 0);
  EXPECT_EQ(t.order(5), 1);
  EXPECT_DOUBLE_EQ(t.length(0), 10.0);
  EXPECT_DOUBLE_EQ(t.radius(1), 0.9);  // Diameter / 2
  // No coordinates: a turtle draws it. The trunk goes up, lengths are the Length feature, and
  // the branch leaves its bearer at 45 degrees.
  EXPECT_NEAR(t.end(1).z(), 18.0, 1e-12);
  EXPECT_NEAR((t.end(2) - t.start(2)).norm(), 5.0, 1e-12);
  EXPECT_NEAR(t.direction(2).dot(t.direction(1)), std::cos(std::numbers::pi / 4), 1e-12);
  EXPECT_EQ(t.start(4), t.end(1));
  EXPECT_FALSE(t.has_attribute("Date"));  // a date is not a number
  // What the coarser scales group: each internode's growth unit and plant, and its own label.
  ASSERT_TRUE(t.has_attribute("U_index"));
  const std::vector<double> unit = {1, 1, 1, 1, 2, 3};
  for (NodeId n = 0; n < t.size(); ++n) {
    EXPECT_EQ(t.attribute("U_index")[n], unit[n]) << n;
    EXPECT_EQ(t.attribute("P_index")[n], 1.0);
    EXPECT_EQ(t.attribute("index")[n], static_cast<double>(n + 1));
  }
}

// Imported, exported and imported again: the label numbers of the first file survive as the
// features they were exported as, not replaced by the new file's labels.
TEST(MtgRead, IndicesOfAnImportedFileSurviveAnotherRoundTrip) {
  const TreeGraph t = parse_mtg(kMultiscale, "plant.mtg");
  std::ostringstream out;
  write_mtg(t, out);
  const TreeGraph again = parse_mtg(out.str(), "again.mtg");
  ASSERT_EQ(again.size(), t.size());
  double units = 0.0, indices = 0.0;
  for (NodeId n = 0; n < again.size(); ++n) {
    units += again.attribute("U_index")[n];
    indices += again.attribute("index")[n];
  }
  EXPECT_EQ(units, 1 + 1 + 1 + 1 + 2 + 3);
  EXPECT_EQ(indices, 1 + 2 + 3 + 4 + 5 + 6);
}

TEST(MtgRead, LeavesFlowersAndAttributes) {
  const std::string text =
      "MTG:\nENTITY-CODE\t\tXX\tYY\tZZ\tLength\tRadius\tnitrogen\n"
      "/P1\n"
      "^/I1\t\t0\t0\t1\t1\t0.1\t2.5\n"
      "\t+L2\t0.3\t0\t1\t0\t0.2\t\n"
      "^<I3\t\t0\t0\t2\t1\t0.05\t1.5\n"
      "\t+F4\t0\t0.2\t2.2\t0.2828\t0.01\t\n";
  const TreeGraph t = parse_mtg(text, "x.mtg");
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t.kind(1), OrganKind::kLeaf);
  EXPECT_EQ(t.kind(3), OrganKind::kFlower);
  EXPECT_EQ(t.start(1), t.end(1));                  // Length 0: a point organ
  EXPECT_EQ(t.start(0), Eigen::Vector3d(0, 0, 0));  // the root starts Length below its top
  EXPECT_EQ(t.start(2), Eigen::Vector3d(0, 0, 1));
  EXPECT_DOUBLE_EQ(t.attribute("nitrogen")[2], 1.5);
  EXPECT_TRUE(std::isnan(t.attribute("nitrogen")[1]));
}

TEST(MtgRead, MistakesNameTheLine) {
  const auto line_of = [](const std::string& text) {
    try {
      parse_mtg(text, "bad.mtg");
    } catch (const ParseError& e) {
      return e.line();
    }
    return -1;
  };
  EXPECT_EQ(line_of("CODE:\tFORM-A\n"), 1);  // no MTG section
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1\n^/I1\t\tten\n"), 4);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1\n^*I1\t\t1\n"), 4);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1\n\t\t\n\t^<I2\t1\n"), 5);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\n/P1/I1\n/P2/I2\n"), 4);  // a second plant
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\n<I1\n"), 3);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1/I1\t\t1\t7\n"), 3);  // extra value
  EXPECT_NO_THROW(parse_mtg("MTG:\nENTITY-CODE\n/P1\n", "empty.mtg"));
  EXPECT_EQ(parse_mtg("MTG:\nENTITY-CODE\n/P1\n", "empty.mtg").size(), 0u);
}

}  // namespace
}  // namespace fspm
