// fspm crown, run as a user would on the example picture of a rendered tree.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

const std::string kPhoto = std::string(FSPM_SOURCE_DIR) + "/examples/crown/tree_front.png";

// The vertex and face counts of a binary PLY header, read independently of fspm's writer.
std::pair<long, long> ply_counts(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long vertices = -1, faces = -1;
  while (std::getline(in, line) && line != "end_header") {
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stol(line.substr(15));
    if (line.rfind("element face ", 0) == 0) faces = std::stol(line.substr(13));
  }
  return {vertices, faces};
}

TEST(CrownCli, ReconstructsTheExamplePictureAndWritesEveryOutput) {
  const auto dir = scratch_dir("crown");
  const auto r = run_fspm("crown " + kPhoto + " --image-height-m 8 -o " +
                          (dir / "tree.ply").string() + " --billboards --json");
  if (r.err.find("without OpenImageIO") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"silhouette_pixels", "vertices", "triangles", "volume_m3", "seconds"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_TRUE(j["seconds"].contains("base_mesh"));
  EXPECT_GT(j["volume_m3"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["metres_per_pixel"].get<double>(), 8.0 / 256.0);
  const auto [vertices, faces] = ply_counts(dir / "tree.ply");
  EXPECT_EQ(vertices, j["vertices"].get<long>());
  EXPECT_EQ(faces, j["triangles"].get<long>());
  for (const char* name : {"tree_color_cubemap.png", "tree_radius_cubemap.exr", "tree_relief.png",
                           "tree_mask.png", "tree_billboards.csv"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  }
}

// "-o crown/" (as in docs/crown.md) is the directory crown, made when missing, not a file
// inside a missing directory crown.
TEST(CrownCli, OutputWithATrailingSlashIsADirectoryThatIsMade) {
  const auto dir = scratch_dir("crown_slash");
  const auto r = run_fspm("crown " + kPhoto + " -o " + (dir / "crown").string() + "/");
  if (r.err.find("without OpenImageIO") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "crown" / "crown.glb"));
  EXPECT_TRUE(std::filesystem::exists(dir / "crown" / "crown_mask.png"));
}

TEST(CrownCli, MistakesFailInOneLineAndWriteNothing) {
  const auto dir = scratch_dir("crown_bad");
  auto r = run_fspm("crown " + kPhoto + " -o " + (dir / "missing" / "x.glb").string());
  if (r.err.find("without OpenImageIO") != std::string::npos) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  r = run_fspm("crown " + kPhoto + " -o " + (dir / "x.xyz").string());
  EXPECT_EQ(r.exit_code, 1);
  r = run_fspm("crown " + (dir / "none.png").string() + " -o " + (dir / "x.glb").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace fspm
