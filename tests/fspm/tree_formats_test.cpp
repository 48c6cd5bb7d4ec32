#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "fspm/binary_tree_format.hpp"
#include "fspm/error.hpp"
#include "fspm/mtg_format.hpp"
#include "fspm/nesting_depth.hpp"
#include "fspm/newick_format.hpp"
#include "fspm/text_tree_format.hpp"
#include "fspm/tree_file.hpp"
#include "tests/fspm/random_tree.hpp"

namespace fspm {
namespace {

TEST(TextFormat, RandomTreesRoundTripBitIdentical) {
  std::mt19937_64 rng(42);
  for (int rep = 0; rep < 25; ++rep) {
    TreeGraph t = testing::random_tree(rng, 1 + rep * 13, rep % 4);
    if (rep % 5 == 0 && t.has_attribute("attr0")) {
      t.attribute("attr0")[0] = std::numeric_limits<double>::quiet_NaN();
    }
    std::stringstream s;
    write_tree_text(t, s);
    const TreeGraph back = read_tree_text(s, "mem");
    EXPECT_TRUE(back.identical(t)) << "rep " << rep;
  }
}

TEST(BinaryFormat, RandomTreesRoundTripBitIdentical) {
  std::mt19937_64 rng(43);
  for (int rep = 0; rep < 25; ++rep) {
    const TreeGraph t = testing::random_tree(rng, 1 + rep * 17, rep % 3);
    std::stringstream s;
    write_tree_binary(t, s);
    const TreeGraph back = read_tree_binary(s, "mem");
    EXPECT_TRUE(back.identical(t)) << "rep " << rep;
  }
}

TEST(TextFormat, ErrorsNameLineColumnAndExpectation) {
  const std::string good =
      "fspm-tree 1\nnodes 2\n0 - internode 1 0 0 0 0 0 0 1 0 0 1 1 0.1 0\n"
      "1 0 internode 1 0 0 0 1 0 0 2 0 0 1 1 0.1 0\n";
  std::istringstream in(good);
  EXPECT_EQ(read_tree_text(in, "ok.tree").size(), 2u);

  auto error_of = [](const std::string& text) {
    std::istringstream s(text);
    try {
      read_tree_text(s, "bad.tree");
    } catch (const ParseError& e) {
      return std::make_tuple(e.line(), e.column(), std::string(e.what()));
    }
    return std::make_tuple(-1, -1, std::string());
  };
  auto [line, col, what] = error_of(
      "fspm-tree 1\nnodes 2\n0 - internode 1 0 0 0 0 0 0 1 0 0 1 1 0.1 0\n"
      "1 0 internode 1 0 0 0 x 0 0 2 0 0 1 1 0.1 0\n");
  EXPECT_EQ(line, 4);
  EXPECT_EQ(col, 23);
  EXPECT_NE(what.find("bad.tree:4:23"), std::string::npos) << what;
  EXPECT_NE(what.find("expected a number"), std::string::npos) << what;

  std::tie(line, col, what) =
      error_of("fspm-tree 1\nnodes 3\n0 - internode 1 0 0 0 0 0 0 1 0 0 1 1 0.1 0\n");
  EXPECT_NE(what.find("ends after 1 of 3"), std::string::npos) << what;
  std::tie(line, col, what) = error_of("hello\n");
  EXPECT_EQ(line, 1);
  std::tie(line, col, what) = error_of(
      "fspm-tree 1\nnodes 2\n0 - internode 1 0 0 0 0 0 0 1 0 0 1 1 0.1 0\n"
      "1 1 internode 1 0 0 0 1 0 0 2 0 0 1 1 0.1 0\n");
  EXPECT_NE(what.find("must come before"), std::string::npos) << what;
  std::tie(line, col, what) =
      error_of("fspm-tree 1\nnodes 1\n0 - stem 1 0 0 0 0 0 0 1 0 0 1 1 0.1 0\n");
  EXPECT_NE(what.find("unknown organ kind"), std::string::npos) << what;
}

TEST(BinaryFormat, TruncatedAndCorruptInputsThrow) {
  std::mt19937_64 rng(44);
  const TreeGraph t = testing::random_tree(rng, 40);
  std::stringstream s;
  write_tree_binary(t, s);
  const std::string bytes = s.str();
  for (std::size_t cut : {0ul, 5ul, 20ul, bytes.size() / 2, bytes.size() - 1}) {
    std::istringstream in(bytes.substr(0, cut));
    EXPECT_THROW(read_tree_binary(in, "cut.treeb"), ParseError) << cut;
  }
  std::string corrupt = bytes;
  corrupt[0] = 'X';
  std::istringstream in(corrupt);
  EXPECT_THROW(read_tree_binary(in, "bad.treeb"), ParseError);
}

TEST(Newick, ParsesLabelsAndTopology) {
  const TreeGraph t = parse_newick("(100,(200,300)1)1000;");
  ASSERT_EQ(t.size(), 5u);
  const auto label = t.attribute("label");
  EXPECT_DOUBLE_EQ(label[0], 1000);
  EXPECT_DOUBLE_EQ(label[1], 100);
  EXPECT_DOUBLE_EQ(label[2], 1);
  EXPECT_DOUBLE_EQ(label[3], 200);
  EXPECT_DOUBLE_EQ(label[4], 300);
  EXPECT_EQ(t.parent(3), 2u);
  EXPECT_EQ(t.child_count(0), 2u);
}

TEST(Newick, RoundTripsStringsExactly) {
  for (const std::string s : {"(100,(200,300)1)1000;", "((1,2)3,(4,(5,6)7)8)9;", "(,);", "1;",
                              "((,(,)),);", "(1:0.5,2:1.25)3:0;", "(0.1,-2.5e-07)1e+20;"}) {
    EXPECT_EQ(to_newick(parse_newick(s)), s);
  }
  EXPECT_EQ(to_newick(parse_newick(" ( 1 , 2 ) 3 ;\n")), "(1,2)3;");
}

TEST(Newick, MalformedInputNamesLineAndColumn) {
  struct Case {
    std::string text;
    int line, column;
    std::string expected;
  };
  for (const Case& c : std::vector<Case>{{"(1,2", 1, 1, "never closed"},
                                         {"(1,2));", 1, 6, "expected ';'"},
                                         {"(1,'abc)3;", 1, 4, "quoted label"},
                                         {"(1,\n2)[x;", 2, 3, "comment"},
                                         {"(1,2)3", 1, 7, "expected ';'"},
                                         {"", 1, 1, "empty"},
                                         {"(1:,2);", 1, 4, "branch length"},
                                         {"(1,2);(3);", 1, 7, "end of the input"}}) {
    try {
      parse_newick(c.text, "t.nwk");
      ADD_FAILURE() << "no error for " << c.text;
    } catch (const ParseError& e) {
      EXPECT_EQ(e.line(), c.line) << c.text << ": " << e.what();
      EXPECT_EQ(e.column(), c.column) << c.text << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
    }
  }
}

// Taxon names as node labels; ids in the order the nodes open: 0 the root, 1 C, 2 A, 3 B, 4 D.
TEST(Newick, ReadsTaxonNamesAndBranchLengths) {
  const NamedTree t = parse_newick_named("((A:1,B:2)C:0.5,D:1);");
  ASSERT_EQ(t.tree.size(), 5u);
  EXPECT_EQ(t.names, (std::vector<std::string>{"", "C", "A", "B", "D"}));
  EXPECT_EQ(t.tree.parent(1), 0u);
  EXPECT_EQ(t.tree.parent(2), 1u);
  EXPECT_EQ(t.tree.parent(3), 1u);
  EXPECT_EQ(t.tree.parent(4), 0u);
  const auto length = t.tree.attribute("branch_length");
  EXPECT_TRUE(std::isnan(length[0]));
  EXPECT_EQ(length[1], 0.5);
  EXPECT_EQ(length[2], 1.0);
  EXPECT_EQ(length[3], 2.0);
  EXPECT_EQ(length[4], 1.0);
  // Names are not numbers: the numeric label stays NaN everywhere.
  for (const double v : t.tree.attribute("label")) EXPECT_TRUE(std::isnan(v));
  // parse_newick reads the same tree without the names.
  EXPECT_TRUE(parse_newick("((A:1,B:2)C:0.5,D:1);").identical(t.tree));
}

TEST(Newick, ReadsQuotedLabelsUnderscoresCommentsAndNumbers) {
  const NamedTree t =
      parse_newick_named("[&R] ('a b':1,'it''s',Quercus_robur[95],'7')'(root), node':2;");
  ASSERT_EQ(t.tree.size(), 5u);
  EXPECT_EQ(t.names,
            (std::vector<std::string>{"(root), node", "a b", "it's", "Quercus robur", "7"}));
  EXPECT_EQ(t.tree.child_count(0), 4u);
  EXPECT_EQ(t.tree.attribute("branch_length")[0], 2.0);
  EXPECT_EQ(t.tree.attribute("branch_length")[1], 1.0);
  // A quoted number is a name; an unquoted one is the numeric label.
  EXPECT_TRUE(std::isnan(t.tree.attribute("label")[4]));
  const NamedTree mixed = parse_newick_named("(A,B)95;");
  EXPECT_EQ(mixed.tree.attribute("label")[0], 95.0);
  EXPECT_EQ(mixed.names, (std::vector<std::string>{"", "A", "B"}));
}

TEST(Newick, OneNodeTrees) {
  const NamedTree number = parse_newick_named("10;");
  ASSERT_EQ(number.tree.size(), 1u);
  EXPECT_EQ(number.tree.attribute("label")[0], 10.0);
  EXPECT_EQ(number.names, std::vector<std::string>{""});
  const NamedTree name = parse_newick_named("A;");
  ASSERT_EQ(name.tree.size(), 1u);
  EXPECT_TRUE(std::isnan(name.tree.attribute("label")[0]));
  EXPECT_EQ(name.names, std::vector<std::string>{"A"});
  const NamedTree quoted = parse_newick_named("'Fagus sylvatica':3;");
  ASSERT_EQ(quoted.tree.size(), 1u);
  EXPECT_EQ(quoted.names, std::vector<std::string>{"Fagus sylvatica"});
  EXPECT_EQ(quoted.tree.attribute("branch_length")[0], 3.0);
}

TEST(Newick, WritesNamesBackQuotedWhereNeeded) {
  for (const std::string s :
       {"((A:1,B:2)C:0.5,D:1);", "A;", "('a b','it''s')'x,y';", "(A,B)95;", "('7',A)B;"}) {
    const NamedTree t = parse_newick_named(s);
    EXPECT_EQ(to_newick_named(t.tree, t.names), s);
  }
  // An empty quoted label is no label.
  const NamedTree empty = parse_newick_named("(A)'';");
  EXPECT_EQ(to_newick_named(empty.tree, empty.names), "(A);");
  // '_' reads as a blank, so a name with a blank or an underscore is written quoted.
  const NamedTree t = parse_newick_named("(Quercus_robur,'Q_r');");
  EXPECT_EQ(t.names[1], "Quercus robur");
  EXPECT_EQ(t.names[2], "Q_r");
  EXPECT_EQ(to_newick_named(t.tree, t.names), "('Quercus robur','Q_r');");
  // Without names, the numbers only.
  EXPECT_EQ(to_newick(t.tree), "(,);");
  const std::vector<std::string> too_few{"A"};
  EXPECT_THROW(to_newick_named(t.tree, too_few), ValueError);
}

TEST(Newick, DeepNestingDoesNotOverflowTheStack) {
  const int depth = 200000;
  const std::string text = std::string(depth, '(') + "1" + std::string(depth, ')') + ";";
  const TreeGraph t = parse_newick(text);
  EXPECT_EQ(t.size(), static_cast<std::size_t>(depth) + 1);
  EXPECT_EQ(to_newick(t), text);
  // Input that is nothing but nesting stops at the bound, with its position.
  const std::string deeper = std::string(kMaxTreeDepth + 1, '(');
  try {
    parse_newick(deeper, "deep.nwk");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.column(), kMaxTreeDepth + 1);
  }
}

TEST(Mtg, WritesSuccessorsAndBranchesInColumns) {
  // Trunk 0-1 with a branch 2 on node 0.
  TreeGraph t;
  NodeData d;
  d.end = {0, 0, 1};
  t.add_node(kNoNode, d);
  d.start = {0, 0, 1};
  d.end = {0, 0, 2};
  t.add_node(0, d);
  d.order = 1;
  d.end = {1, 0, 1};
  t.add_node(0, d);
  std::ostringstream out;
  write_mtg(t, out);
  const std::string s = out.str();
  EXPECT_NE(s.find("CODE:\tFORM-A"), std::string::npos);
  EXPECT_NE(s.find("\n/P1\n^/I1\t\t0\t0\t1\t"), std::string::npos) << s;
  EXPECT_NE(s.find("\n\t+I3\t1\t0\t1\t"), std::string::npos) << s;
  EXPECT_NE(s.find("\n^<I2\t\t0\t0\t2\t"), std::string::npos) << s;
  // The branch is written before the successor so that "^<" refers back to I1.
  EXPECT_LT(s.find("+I3"), s.find("^<I2"));
}

TEST(TreeFile, ChoosesFormatByExtensionAndWritesAtomically) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "fspm_tree_file_test";
  fs::create_directories(dir);
  std::mt19937_64 rng(45);
  const TreeGraph t = testing::random_tree(rng, 30);
  for (const char* ext : {".tree", ".treeb"}) {
    const std::string path = (dir / (std::string("t") + ext)).string();
    write_tree_file(t, path);
    EXPECT_TRUE(read_tree_file(path).identical(t)) << ext;
  }
  EXPECT_THROW(tree_format_for("x.xyz"), ValueError);
  EXPECT_EQ(tree_format_for("x.tree", "nwk"), TreeFormat::kNewick);
  EXPECT_THROW(read_tree_file((dir / "missing.tree").string()), IoError);
  EXPECT_THROW(write_tree_file(t, (dir / "no/such/dir/t.tree").string()), IoError);
  // A failing writer leaves neither the target nor a temporary file behind.
  TreeGraph bad = t;
  bad.add_attribute("has space", 0.0);
  const fs::path target = dir / "bad.tree";
  fs::remove(target);
  EXPECT_THROW(write_tree_file(bad, target.string()), ValueError);
  EXPECT_FALSE(fs::exists(target));
  for (const auto& e : fs::directory_iterator(dir)) {
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fspm
