// fspm scan, fspm encode and fspm tree convert of a grouped OBJ, run as a user would.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

const std::string kTree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";

TEST(ScanCli, ScanThenEncodeReportsWhatItWrote) {
  const auto dir = scratch_dir("scan_encode");
  const std::string scan = (dir / "scan.ply").string();
  auto r = run_fspm("scan " + kTree + " -o " + scan + " --seed 3 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = nlohmann::json::parse(r.out);
  ASSERT_GT(s["points"].get<std::size_t>(), 1000u);
  const std::string model = (dir / "tree.clusters").string();
  r = run_fspm("encode " + scan + " --species pine --fs 0.9 -o " + model + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], s["points"]);
  EXPECT_EQ(j["bytes"].get<std::uintmax_t>(), std::filesystem::file_size(model));
  EXPECT_GE(j["skeleton_nodes"].get<int>(), 1);
  EXPECT_DOUBLE_EQ(j["beta"].get<double>(), 1.3);  // pine, Pirk Table 3.1
  EXPECT_DOUBLE_EQ(j["f_s"].get<double>(), 0.9);   // overridden
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
}

TEST(ScanCli, MistakesExitWithOneLine) {
  const auto dir = scratch_dir("scan_bad");
  const std::string xyz = (dir / "p.xyz").string();
  std::ofstream(xyz) << "0 0 0\n0 0 1\n0 0 x\n";
  auto r = run_fspm("encode " + xyz + " -o " + (dir / "m.clusters").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(":3"), std::string::npos) << r.err;  // the line
  r = run_fspm("encode " + kTree + " --species pinus -o " + (dir / "n.clusters").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("pine"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "n.clusters"));
}

TEST(ScanCli, TreeConvertReadsAGroupedObj) {
  const auto dir = scratch_dir("scan_obj");
  const std::string obj = (dir / "branches.obj").string();
  std::ofstream out(obj);
  int v = 1;
  const auto square = [&](double x, double y, double z, double w) {
    for (const auto& [dx, dy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      out << "v " << x + dx * w / 2 << ' ' << y + dy * w / 2 << ' ' << z << '\n';
    }
    out << "f " << v << ' ' << v + 1 << ' ' << v + 2 << ' ' << v + 3 << '\n';
    v += 4;
  };
  out << "g trunk1\n";
  for (int k = 0; k < 4; ++k) square(0, 0, k, 0.3);
  out << "g branch1\n";
  for (int k = 1; k <= 2; ++k) square(0.4 * k, 0, 1.1 + 0.3 * k, 0.1);
  out.close();
  const std::string tree = (dir / "tree.tree").string();
  const auto r = run_fspm("tree convert " + obj + " " + tree);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TreeGraph t = read_tree_file(tree);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t.parent(3), 0u);  // the branch hangs at the trunk point z = 1
  EXPECT_NEAR(t.radius(4), 0.05, 1e-9);
}

}  // namespace
}  // namespace fspm
