// fspm crown, run as a user would on the example picture of a rendered tree.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "graphics/image.hpp"
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
                           "tree_mask.png", "tree_billboards.csv", "tree_cubemaps.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  }
}

// Pixels of the crown's dark foliage greens (the example tree's), not of the sky or of the ground,
// whose green barely exceeds its red.
std::size_t foliage_pixels(const graphics::Image& image) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      n += p[1] > p[0] + 30 && p[1] > p[2] + 30;
    }
  }
  return n;
}

// A scene placing the crown fspm crown wrote to dir/oak twice, once turned and halved: by its
// folder and by its mesh.
void write_two_crown_scene(const std::filesystem::path& dir) {
  testing::write_text(dir / "scene.json",
                      R"({"fspm_scene": 2, "plants": [{"crown": "oak/", "position": [-6, 0, 0]},
                          {"crown": "oak/crown.glb", "position": [5, 2, 0], "rotation_deg": 90,
                           "scale": 0.5}]})");
}

// fspm view CROWN --ray-cast ray casts the crown from its cubemaps (Argudo 5.1), found through the
// description fspm crown writes beside the mesh; without that description it says what is
// missing, and it refuses anything but one crown mesh.
TEST(CrownCli, ViewerRayCastsTheCrownFromItsCubemaps) {
  const auto dir = scratch_dir("crown_relief");
  auto r = run_fspm("crown " + kPhoto + " -o " + (dir / "oak").string() + " --json");
  if (r.err.find("without OpenImageIO") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto made = nlohmann::json::parse(r.out);
  std::ifstream in(dir / "oak" / "crown_cubemaps.json");
  const auto d = nlohmann::json::parse(in);
  EXPECT_EQ(d["cubemap_size"], made["cubemap_size"]);
  EXPECT_EQ(d["radius_cubemap"], "crown_radius_cubemap.exr");
  EXPECT_EQ(d["centre_m"].size(), 3u);
  const std::string mesh = (dir / "oak" / "crown.glb").string();
  r = run_fspm("view " + mesh + " --ray-cast --no-panel --size 160x120 --json --screenshot " +
               (dir / "relief.png").string());
  if (r.err.find("without the viewer") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 0);  // no trunk: the crown is ray cast
  // The crown fills a good part of the picture (the photograph's crown seen from the front).
  EXPECT_GT(foliage_pixels(graphics::read_image((dir / "relief.png").string())), 160u * 120u / 20);
  // Without --ray-cast the viewer draws the mesh itself; the folder stands for its crown.
  r = run_fspm("view " + (dir / "oak").string() +
               " --no-panel --size 160x120 --json --screenshot " + (dir / "mesh.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], made["triangles"]);
  EXPECT_GT(foliage_pixels(graphics::read_image((dir / "mesh.png").string())), 160u * 120u / 20);
  // A scene placing the crown twice, once turned and halved: both ray cast, nothing meshed.
  write_two_crown_scene(dir);
  r = run_fspm("view " + (dir / "scene.json").string() +
               " --ray-cast --no-panel --size 160x120 --json --screenshot " +
               (dir / "scene.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 0);
  // Two crowns, one at half size, shaded darker low in the crown (Argudo 5.3).
  EXPECT_GT(foliage_pixels(graphics::read_image((dir / "scene.png").string())), 160u * 120u / 30);
  testing::write_text(dir / "trees.json", R"({"fspm_scene": 2, "plants": [{"file": ")" +
                                              std::string(FSPM_SOURCE_DIR) +
                                              R"(/examples/trees/open_a12.treeb"}]})");
  r = run_fspm("view " + (dir / "trees.json").string() + " --ray-cast");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("places no crown"), std::string::npos) << r.err;
  r = run_fspm("view " + std::string(FSPM_SOURCE_DIR) +
               "/examples/trees/open_a12.treeb --ray-cast");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--ray-cast draws the crowns of one crown file"), std::string::npos)
      << r.err;
  std::filesystem::remove(dir / "oak" / "crown_cubemaps.json");
  r = run_fspm("view " + mesh + " --ray-cast --screenshot " + (dir / "x.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("written by fspm crown"), std::string::npos) << r.err;
}

// fspm render --ray-cast draws the crown from its cubemaps into the VTK picture, where the mesh
// path draws its triangles: both cover the crown's pixels; a scene's copies are all ray cast.
TEST(CrownCli, RenderRayCastsTheCrownFromItsCubemaps) {
  const auto dir = scratch_dir("crown_render");
  auto r = run_fspm("crown " + kPhoto + " -o " + (dir / "oak").string());
  if (r.err.find("without OpenImageIO") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string mesh = (dir / "oak" / "crown.glb").string();
  // The folder fspm crown wrote stands for its crown, as in view and scene files.
  r = run_fspm("render " + (dir / "oak").string() +
               " --ray-cast --view front --size 160x120 --json -o " +
               (dir / "relief.png").string());
  if (r.err.find("without VTK") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 0);  // no trunk: the crown is ray cast
  EXPECT_GT(foliage_pixels(graphics::read_image((dir / "relief.png").string())), 160u * 120u / 20);
  write_two_crown_scene(dir);
  r = run_fspm("render " + (dir / "scene.json").string() +
               " --ray-cast --view front --size 160x120 --json -o " + (dir / "scene.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 0);
  EXPECT_GT(foliage_pixels(graphics::read_image((dir / "scene.png").string())), 160u * 120u / 30);
  r = run_fspm("mesh " + (dir / "oak").string() + " -o " + (dir / "crown.obj").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("render " + mesh + " --ray-cast --lod -o " + (dir / "x.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--ray-cast takes no"), std::string::npos) << r.err;
  r = run_fspm("render " + std::string(FSPM_SOURCE_DIR) +
               "/examples/trees/open_a12.treeb --ray-cast -o " + (dir / "x.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--ray-cast draws the crowns of one crown file"), std::string::npos)
      << r.err;
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
