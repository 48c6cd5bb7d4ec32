// fspm decode, run as a user would: a scanned tree encoded, then decoded into a tree file and
// meshes (instanced .glb, explicit .ply), with stochastic pruning and seeds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

const std::string kTree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";

std::string encoded_model(const std::filesystem::path& dir) {
  const std::string scan = (dir / "scan.ply").string();
  const std::string model = (dir / "tree.clusters").string();
  auto r = run_fspm("scan " + kTree + " -o " + scan + " --seed 3");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("encode " + scan + " --fs 0.9 -o " + model);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return model;
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(DecodeCli, TreeAndMeshesReportWhatTheyWrote) {
  const auto dir = scratch_dir("decode");
  const std::string model = encoded_model(dir);
  const std::string tree = (dir / "decoded.tree").string();
  auto r = run_fspm("decode " + model + " -o " + tree + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto t = nlohmann::json::parse(r.out);
  EXPECT_EQ(t["nodes"].get<std::size_t>(), read_tree_file(tree).size());
  EXPECT_GT(t["instances"].get<std::size_t>(), 0u);
  EXPECT_GE(t["seconds"].get<double>(), 0.0);
  // Textured up to the clusters' scanned branch length; each cluster ends within half a patch of
  // it (patches are at most the species' size, 2-3 m of internodes).
  const double scanned_m = t["scanned_branch_length_m"].get<double>();
  EXPECT_GT(scanned_m, 0.0);
  EXPECT_GE(t["branch_length_m"].get<double>(), 0.9 * scanned_m);
  EXPECT_LE(t["branch_length_m"].get<double>(), 1.3 * scanned_m);
  // Pirk's texturing alone ends when the docking points are used up, short of it on this tree.
  r = run_fspm("decode " + model + " -o " + (dir / "pirk.tree").string() +
               " --docking-only --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto pirk = nlohmann::json::parse(r.out);
  EXPECT_LT(pirk["branch_length_m"].get<double>(), 0.9 * scanned_m);

  const std::string glb = (dir / "decoded.glb").string();
  r = run_fspm("decode " + model + " -o " + glb + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto full = nlohmann::json::parse(r.out);
  EXPECT_EQ(full["nodes"], t["nodes"]);
  EXPECT_EQ(full["instances"], t["instances"]);
  // Each patch stored once: fewer stored than drawn triangles.
  EXPECT_LT(full["stored_triangles"].get<std::size_t>(), full["triangles"].get<std::size_t>());
  EXPECT_TRUE(std::filesystem::file_size(glb) > 0);

  // Seen from 500 m, each patch draws a prefix of its leaves: fewer triangles, same patches.
  r = run_fspm("decode " + model + " -o " + (dir / "far.glb").string() + " --lod 500 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto far = nlohmann::json::parse(r.out);
  EXPECT_EQ(far["instances"], full["instances"]);
  EXPECT_LT(far["triangles"].get<std::size_t>(), full["triangles"].get<std::size_t>());
}

TEST(DecodeCli, SameSeedSameFile) {
  const auto dir = scratch_dir("decode_seed");
  const std::string model = encoded_model(dir);
  const std::string a = (dir / "a.ply").string(), b = (dir / "b.ply").string();
  ASSERT_EQ(run_fspm("decode " + model + " -o " + a + " --seed 4").exit_code, 0);
  ASSERT_EQ(run_fspm("decode " + model + " -o " + b + " --seed 4").exit_code, 0);
  EXPECT_TRUE(bytes_of(a) == bytes_of(b));  // binary PLY: no file names inside
  const std::string c = (dir / "c.ply").string();
  ASSERT_EQ(run_fspm("decode " + model + " -o " + c + " --seed 5").exit_code, 0);
  EXPECT_FALSE(bytes_of(a) == bytes_of(c));
}

TEST(DecodeCli, MistakesExitWithOneLine) {
  const auto dir = scratch_dir("decode_bad");
  const std::string junk = (dir / "junk.clusters").string();
  std::ofstream(junk) << "not a clusters file";
  auto r = run_fspm("decode " + junk + " -o " + (dir / "x.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("junk.clusters"), std::string::npos) << r.err;
  const std::string model = encoded_model(dir);
  r = run_fspm("decode " + model + " -o " + (dir / "x.tree").string() + " --lod 30");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--lod"), std::string::npos) << r.err;
  r = run_fspm("decode " + model + " --species pinus -o " + (dir / "y.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "y.tree"));
}

}  // namespace
}  // namespace fspm
