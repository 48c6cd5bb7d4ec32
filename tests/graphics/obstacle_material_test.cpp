// The obstacle material (walls and boxes of a growth scene) through every exporter and renderer.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "graphics/instanced_mesh.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "graphics/vtk_readback.hpp"
#include "tests/graphics/image_checks.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

// A vertical square of side 1 in the plane y = y0, x in [x0, x0 + 1], z in [0, 1], facing -y.
TriangleMesh stone_square(float x0, float y0) {
  TriangleMesh m;
  for (const auto& [x, z] : {std::pair{0.f, 0.f}, {1.f, 0.f}, {1.f, 1.f}, {0.f, 1.f}}) {
    m.positions.emplace_back(x0 + x, y0, z);
    m.normals.emplace_back(0, -1, 0);
    m.uvs.emplace_back(x, z);
  }
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.materials = {Material::kObstacle, Material::kObstacle};
  return m;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class ObstacleMaterial : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fspm_obstacle_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    MeshOptions o;
    o.leaves = true;
    tree_ = mesh_tree(testing::small_tree(), o);
    mesh_ = tree_;
    mesh_.append(stone_square(0.5f, -0.5f));
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  TriangleMesh tree_, mesh_;
};

TEST_F(ObstacleMaterial, NameColourAndIndex) {
  EXPECT_EQ(material_name(Material::kObstacle), "obstacle");
  EXPECT_EQ(material_from_index(2), Material::kObstacle);
  EXPECT_EQ(material_from_index(7), Material::kBark);
  const auto c = material_color(Material::kObstacle);
  EXPECT_NEAR(c[0], c[1], 0.05);  // neutral: a grey
  EXPECT_NEAR(c[1], c[2], 0.05);
  EXPECT_EQ(mesh_.triangle_count(Material::kObstacle), 2u);
}

TEST_F(ObstacleMaterial, ObjUsesTheObstacleMaterial) {
  write_obj(mesh_, (dir_ / "m.obj").string());
  const std::string obj = slurp(dir_ / "m.obj");
  const auto at = obj.find("usemtl obstacle\n");
  ASSERT_NE(at, std::string::npos);
  std::size_t faces = 0;
  for (auto f = obj.find("\nf ", at); f != std::string::npos; f = obj.find("\nf ", f + 1)) ++faces;
  EXPECT_EQ(faces, 2u);  // exactly the square's triangles follow it
  EXPECT_NE(slurp(dir_ / "m.mtl").find("newmtl obstacle"), std::string::npos);
}

TEST_F(ObstacleMaterial, PlyStoresMaterialTwo) {
  write_ply(mesh_, (dir_ / "m.ply").string());
  const std::string data = slurp(dir_ / "m.ply");
  // Faces (uchar 3, 3 uint, uchar material = 14 bytes) end the file; the last two are the square.
  ASSERT_GT(data.size(), 28u);
  EXPECT_EQ(data[data.size() - 1], 2);
  EXPECT_EQ(data[data.size() - 15], 2);
  EXPECT_EQ(data[data.size() - 29], 1);  // the last leaf triangle before them
}

TEST_F(ObstacleMaterial, GlbHasOneMaterialPerKind) {
  write_glb(mesh_, (dir_ / "m.glb").string());
  const std::string data = slurp(dir_ / "m.glb");
  std::uint32_t json_len = 0;
  std::memcpy(&json_len, data.data() + 12, 4);
  const auto doc = nlohmann::json::parse(data.substr(20, json_len));
  ASSERT_EQ(doc["materials"].size(), 6u);
  EXPECT_EQ(doc["materials"][5]["name"], "terrain");
  EXPECT_EQ(doc["materials"][2]["name"], "obstacle");
  EXPECT_FALSE(doc["materials"][2].contains("alphaMode"));  // stone is opaque
  // Obstacles that let light through: blended at their opacity.
  EXPECT_EQ(doc["materials"][4]["name"], "translucent_obstacle");
  EXPECT_EQ(doc["materials"][4]["alphaMode"], "BLEND");
  EXPECT_NEAR(doc["materials"][4]["pbrMetallicRoughness"]["baseColorFactor"][3].get<double>(), 0.4,
              1e-3);
  // Leaf-cluster crowns are seen through: blended, alpha the crown opacity.
  EXPECT_EQ(doc["materials"][3]["name"], "crown");
  EXPECT_EQ(doc["materials"][3]["alphaMode"], "BLEND");
  EXPECT_NEAR(doc["materials"][3]["pbrMetallicRoughness"]["baseColorFactor"][3].get<double>(),
              kCrownOpacity, 1e-3);
  const auto& prims = doc["meshes"][0]["primitives"];
  ASSERT_EQ(prims.size(), 3u);
  EXPECT_EQ(prims[2]["material"], 2);
  EXPECT_EQ(doc["accessors"][prims[2]["indices"].get<std::size_t>()]["count"], 6);
}

TEST_F(ObstacleMaterial, VtpRoundTripKeepsTheMaterial) {
  if (!vtk_available()) GTEST_SKIP() << "built without VTK";
  write_vtp(mesh_, (dir_ / "m.vtp").string());
  const TriangleMesh back = read_vtp_mesh((dir_ / "m.vtp").string());
  EXPECT_EQ(back.materials, mesh_.materials);
  EXPECT_EQ(back.triangle_count(Material::kObstacle), 2u);
}

using testing::stone_pixels;

// A 200 x 160 front view without the ground plane, for counting the obstacles' pixels.
RenderOptions small_front_view() {
  RenderOptions o;
  o.width = 200;
  o.height = 160;
  o.view = View::kFront;
  o.ground = false;
  return o;
}

TEST_F(ObstacleMaterial, RendersDrawTheStoneInFlatInstancedAndColouredPaths) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  RenderOptions o = small_front_view();
  const std::size_t without = stone_pixels(render_mesh(tree_, o));
  EXPECT_GT(stone_pixels(render_mesh(mesh_, o)), without + 400);
  InstancedMesh scene = InstancedMesh::single(tree_);
  scene.meshes.push_back(stone_square(0.5f, -0.5f));
  scene.instances.push_back({1});
  EXPECT_GT(stone_pixels(render_scene(scene, o)), without + 400);
  o.color_by = "light";  // the flattened scene: obstacles in stone, not mapped to light = 0
  o.scalar_bar = false;
  EXPECT_GT(stone_pixels(render_scene(scene, o)), 400u);
}

// Grey pixels no brighter than 200: lit stone (about 160), not stone blended into the pale sky.
std::size_t dark_grey_pixels(const Image& image) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      const int lo = std::min({p[0], p[1], p[2]}), hi = std::max({p[0], p[1], p[2]});
      if (hi - lo < 24 && hi > 60 && hi <= 200) ++n;
    }
  }
  return n;
}

// A translucent obstacle is blended at opacity 0.4 with what lies behind it (the pale sky here):
// its pixels are far lighter than the same square's opaque stone.
TEST_F(ObstacleMaterial, TranslucentObstaclesAreSeenThrough) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  RenderOptions o = small_front_view();
  TriangleMesh clear = tree_;
  TriangleMesh square = stone_square(0.5f, -0.5f);
  for (auto& m : square.materials) m = Material::kTranslucentObstacle;
  clear.append(square);
  const std::size_t opaque = dark_grey_pixels(render_mesh(mesh_, o));
  const std::size_t translucent = dark_grey_pixels(render_mesh(clear, o));
  EXPECT_GT(opaque, 400u);
  EXPECT_LT(translucent, opaque / 2);
}

// Each translucent obstacle is as see-through as its translucency says: a square letting 20 % of
// the light through (opacity 0.8) changes the picture behind it far more than one letting 80 %
// through (opacity 0.2). Measured as the summed colour change against the tree drawn alone.
TEST_F(ObstacleMaterial, OpacityFollowsEachObstaclesTranslucency) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  EXPECT_FLOAT_EQ(translucent_obstacle_opacity(0.2f), 0.8f);
  EXPECT_FLOAT_EQ(translucent_obstacle_opacity(1.0f), 0.15f);
  RenderOptions o = small_front_view();
  o.frame = Eigen::AlignedBox3f(mesh_.bbox_min(), mesh_.bbox_max());  // one frame for all three
  const Image background = render_mesh(tree_, o);
  const auto change = [&](float translucency) {
    TriangleMesh mesh = tree_;
    TriangleMesh square = stone_square(0.5f, -0.5f);
    for (auto& m : square.materials) m = Material::kTranslucentObstacle;
    std::vector<float>& gamma = square.add_attribute("translucency");
    std::fill(gamma.begin(), gamma.end(), translucency);
    mesh.append(square);
    const Image image = render_mesh(mesh, o);
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        for (int c = 0; c < 3; ++c) {
          sum += std::abs(int(image.pixel(x, y)[c]) - int(background.pixel(x, y)[c]));
        }
      }
    }
    return sum;
  };
  const double dense = change(0.2f);
  const double sparse = change(0.8f);
  EXPECT_GT(dense, 0.0);
  EXPECT_GT(dense, 2.5 * sparse);
}

TEST_F(ObstacleMaterial, ViewerDrawsTheStone) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  ViewerOptions o;
  o.width = 240;
  o.height = 180;
  o.frames = 2;
  o.shadows = false;
  o.screenshot = (dir_ / "shot.png").string();
  (void)run_viewer({tree_}, {0.0}, o);
  const std::size_t without = stone_pixels(read_image(o.screenshot));
  (void)run_viewer({mesh_}, {0.0}, o);
  EXPECT_GT(stone_pixels(read_image(o.screenshot)), without + 300);
  o.color_by = "light";  // obstacles stay stone when the plants are coloured
  (void)run_viewer({mesh_}, {0.0}, o);
  EXPECT_GT(stone_pixels(read_image(o.screenshot)), without + 300);
}

// The viewer blends each translucent obstacle at its own opacity, after the opaque geometry: a
// square letting 20 % of the light through (opacity 0.8) changes the picture far more than one
// letting 80 % through (0.2), both measured against the same square letting all light through
// (opacity 0.15, the floor), drawn in the same frame.
TEST_F(ObstacleMaterial, ViewerBlendsEachObstacleAtItsOpacity) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  ViewerOptions o;
  o.width = 240;
  o.height = 180;
  o.shadows = false;
  o.screenshot = (dir_ / "shot.png").string();
  const auto shot = [&](float translucency) {
    TriangleMesh mesh = tree_;
    TriangleMesh square = stone_square(-0.5f, -0.5f);
    for (auto& m : square.materials) m = Material::kTranslucentObstacle;
    std::vector<float>& gamma = square.add_attribute("translucency");
    std::fill(gamma.begin(), gamma.end(), translucency);
    mesh.append(square);
    (void)run_viewer({mesh}, {0.0}, o);
    return read_image(o.screenshot);
  };
  const Image clear = shot(1.0f);
  const auto change = [&](const Image& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        for (int c = 0; c < 3; ++c) {
          sum += std::abs(int(image.pixel(x, y)[c]) - int(clear.pixel(x, y)[c]));
        }
      }
    }
    return sum;
  };
  const double dense = change(shot(0.2f));
  const double sparse = change(shot(0.8f));
  EXPECT_GT(sparse, 0.0);  // the opacity does follow the translucency
  EXPECT_GT(dense, 2.5 * sparse);
  // Alpha stays 1 in the image: blending does not make the screenshot itself see-through.
  const Image image = read_image(o.screenshot);
  EXPECT_EQ(image.pixel(image.width / 2, image.height / 2)[3], 255);
}

}  // namespace
}  // namespace fspm::graphics
