#include "fspm/mtg_format.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/mtg_reader.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/mtg_writer.hpp"
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
      ASSERT_NE(it, by_end.end()) << "rep " << rep << " node " << m << "\n" << out.str();
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
  // A date is days since 1970-01-01: 1 March 1998 is 28 years (7 of them leap years) and the 59
  // days of January and February after it.
  ASSERT_TRUE(t.has_attribute("Date"));
  EXPECT_EQ(t.attribute("Date")[0], 28 * 365 + 7 + 59);
  EXPECT_TRUE(std::isnan(t.attribute("Date")[1]));
  // What the coarser scales group: each internode's growth unit and plant, and its own label.
  ASSERT_TRUE(t.has_attribute("U_index"));
  const std::vector<double> unit = {1, 1, 1, 1, 2, 3};
  for (NodeId n = 0; n < t.size(); ++n) {
    EXPECT_EQ(t.attribute("U_index")[n], unit[n]) << n;
    EXPECT_EQ(t.attribute("P_index")[n], 1.0);
    EXPECT_EQ(t.attribute("index")[n], static_cast<double>(n + 1));
  }
}

// Read, written and read again: the same multiscale graph, labels, relations and features.
TEST(MtgRead, MultiscaleGraphSurvivesWritingAndReading) {
  const Mtg first = read_mtg(kMultiscale, "plant.mtg");
  std::ostringstream out;
  write_mtg(first, out);
  const Mtg again = read_mtg(out.str(), "again.mtg");
  ASSERT_EQ(again.size(), first.size()) << out.str();
  for (MtgVertex v = 0; v < first.size(); ++v) {
    EXPECT_EQ(again.label(v), first.label(v));
    EXPECT_EQ(again.scale(v), first.scale(v));
    EXPECT_EQ(again.complex(v), first.complex(v));
    EXPECT_EQ(again.parent(v), first.parent(v));
    EXPECT_EQ(again.edge(v), first.edge(v));
    for (std::size_t f = 0; f < first.features().size(); ++f) {
      EXPECT_EQ(again.feature_text(v, f), first.feature_text(v, f));
    }
  }
}

TEST(MtgRead, LeavesFlowersAndAttributes) {
  const std::string text =
      "MTG:\nENTITY-CODE\t\tXX\tYY\tZZ\tLength\tRadius\tnitrogen\tOrgan\n"
      "/P1\n"
      "^/I1\t\t0\t0\t1\t1\t0.1\t2.5\n"
      "\t+L2\t0.3\t0\t1\t0\t0.2\t\tleaf\n"
      "^<I3\t\t0\t0\t2\t1\t0.05\t1.5\n"
      "\t+F4\t0\t0.2\t2.2\t0.2828\t0.01\t\tflower\n";
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

// 50 bytes of "+.+" notation make a chain of 210 010 branches on branches (a fuzzing finding):
// written with one tab per level it would take about 44 GB, so the writer refuses it.
TEST(MtgWrite, DeepBranchNestingIsRefusedBeforeWriting) {
  const Mtg g = read_mtg("MTG:\nENTITY-CODE\n/I2+.+nnnnnnnPn210011\n", "deep.mtg");
  ASSERT_GT(g.size(), 200000u);
  // The code's size: each of the 210 011 lines holds its code and is indented to the deepest of
  // 210 010 columns, so at least 210 011 x 210 010 bytes, about 41 GiB.
  const auto expect_refused = [](auto write, const std::string& path) {
    try {
      write();
      ADD_FAILURE() << "no error for " << path;
    } catch (const ValueError& e) {
      EXPECT_EQ(e.file(), path);
      EXPECT_EQ(std::string(e.what()).rfind(path + ": the MTG code would take about ", 0), 0u)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("GiB, expected at most 256 MiB: its branching nests "
                                           "210010 levels deep"),
                std::string::npos)
          << e.what();
    }
  };
  std::ostringstream out;
  expect_refused([&] { write_mtg(g, out, "out/deep.mtg"); }, "out/deep.mtg");
  EXPECT_LT(out.str().size(), 1000u);
  std::ostringstream tree_out;  // the same chain as a TreeGraph (fspm tree convert to .mtg)
  expect_refused([&] { write_mtg(mtg_to_tree(g), tree_out, "tree.mtg"); }, "tree.mtg");
  EXPECT_LT(tree_out.str().size(), 2000u);
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
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1\n^*I1\t\t1\n"), 4);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1\n\t\t\n\t^<I2\t1\n"), 5);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\n<I1\n"), 3);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\nTOPO\n"), 2);  // a second header, no entity
  // Readable with a warning, as OpenAlea reads them: a value not of its type, an extra value.
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1\n^/I1\t\tten\n"), -1);
  EXPECT_EQ(line_of("MTG:\nENTITY-CODE\t\tLength\n/P1/I1\t\t1\t7\n"), -1);
  // A plant without components is a tree of one node, two plants a tree of both.
  EXPECT_EQ(parse_mtg("MTG:\nENTITY-CODE\n/P1\n", "one.mtg").size(), 1u);
  EXPECT_EQ(parse_mtg("MTG:\nENTITY-CODE\t\n/P1/I1\n/P2/I2\n", "two.mtg").size(), 3u);
}

}  // namespace
}  // namespace fspm
