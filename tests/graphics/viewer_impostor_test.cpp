// Impostors in the viewer against full detail. The oracle for how close a view-based stand-in can
// come is the same scene with every plant turned by 15 degrees about its axis, drawn at full
// detail: an impostor shows its plant from the nearest of 24 directions, up to 22.5 degrees of
// azimuth and here 15 degrees of elevation off (the camera looks down 20 degrees, the rings are
// at 0, 35 and 70), so its image differs from the exact one about as much as that turned scene
// does. Sparse, thin plants a few tens of pixels high differ in most of their pixels between two
// such views (silhouette IoU about 0.25 here), so the test holds the impostors to the oracle, not
// to a fixed IoU; the coverage and colour of the plants must match closely.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <functional>

#include "graphics/image.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.141592653589793;
constexpr double kTurnDeg = 15.0;  // the oracle's turn

// A trunk and four levels of three branches each (120 degrees apart, 40 degrees from their
// parent, 0.7 times as long and thin), with a leaf at every tip.
void grow(TreeGraph& t, NodeId parent, const Eigen::Vector3d& base, const Eigen::Vector3d& dir,
          double length, double radius, int level) {
  const Eigen::Vector3d tip = base + length * dir;
  const NodeId n =
      testing::add(t, parent, base, tip, radius, level, static_cast<std::uint16_t>(level));
  if (level == 4) {
    testing::add(t, n, tip, tip + 0.3 * dir, 0.0, level, 5, OrganKind::kLeaf);
    return;
  }
  const Eigen::Vector3d side = dir.unitOrthogonal();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = Eigen::AngleAxisd(2.0 * kPi * k / 3.0 + level, dir) * side;
    const Eigen::Vector3d child = Eigen::AngleAxisd(40.0 * kPi / 180.0, axis) * dir;
    grow(t, n, tip, child.normalized(), 0.7 * length, 0.7 * radius, level + 1);
  }
}

TriangleMesh plant_mesh() {
  TreeGraph t;
  grow(t, kNoNode, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 3.0, 0.15, 0);
  MeshOptions o;
  o.leaves = true;
  return mesh_tree(t, o);
}

// Four specks far apart fix the scene's bounds, so turning the plants does not move the camera.
TriangleMesh bound_specks() {
  TriangleMesh m;
  for (const Eigen::Vector3f& p : {Eigen::Vector3f(-25, -25, 0), Eigen::Vector3f(25, 25, 0),
                                   Eigen::Vector3f(-25, 25, 12), Eigen::Vector3f(25, -25, 12)}) {
    const auto n = static_cast<std::uint32_t>(m.positions.size());
    for (const Eigen::Vector3f& d :
         {Eigen::Vector3f(0, 0, 0), Eigen::Vector3f(1e-3f, 0, 0), Eigen::Vector3f(0, 0, 1e-3f)}) {
      m.positions.push_back(p + d);
      m.normals.push_back(Eigen::Vector3f::UnitY());
      m.uvs.push_back(Eigen::Vector2f::Zero());
    }
    m.triangles.push_back({n, n + 1, n + 2});
    m.materials.push_back(Material::kBark);
  }
  return m;
}

// A 60 m square at z = 0 under the plants, for their shadows.
TriangleMesh ground_square() {
  TriangleMesh m;
  for (const Eigen::Vector3f& p : {Eigen::Vector3f(-30, -30, 0), Eigen::Vector3f(30, -30, 0),
                                   Eigen::Vector3f(30, 30, 0), Eigen::Vector3f(-30, 30, 0)}) {
    m.positions.push_back(p);
    m.normals.push_back(Eigen::Vector3f::UnitZ());
    m.uvs.push_back(Eigen::Vector2f::Zero());
  }
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.materials.assign(2, Material::kObstacle);
  return m;
}

// 16 plants on a 4 x 4 grid 10 m apart, each turned by 37 degrees more than the last, plus
// `extra_deg`.
LodScene grid_scene(double extra_deg, bool ground = false) {
  LodScene scene;
  scene.plants.push_back(make_lod_plant({plant_mesh()}, LodOptions{}, 1));
  for (int i = 0; i < 16; ++i) {
    PartPlacement p;
    const double turn = (37.0 * i + extra_deg) * kPi / 180.0;
    p.linear =
        Eigen::AngleAxisf(static_cast<float>(turn), Eigen::Vector3f::UnitZ()).toRotationMatrix();
    p.translation = Eigen::Vector3f(10.0f * static_cast<float>(i % 4) - 15.0f,
                                    10.0f * static_cast<float>(i / 4) - 15.0f, 0.0f);
    scene.placements.push_back(p);
  }
  scene.fixed.meshes.push_back(ground ? ground_square() : bound_specks());
  scene.fixed.instances.emplace_back();
  return scene;
}

struct Shot {
  Image image;
  ViewerStats stats;
};

// The finest mesh and every leaf up to `impostor_distance_m` (0: everywhere, no impostors).
Shot view(const LodScene& scene, double impostor_distance_m, int frames, const fs::path& file,
          const std::function<void(int, ViewerControls&)>& before_frame = {}) {
  LodOptions lod;
  lod.max_distance_m = impostor_distance_m > 0.0 ? impostor_distance_m : 1e6;
  lod.prune_distance_m = 1e6;
  lod.impostor_distance_m = impostor_distance_m;
  lod.jitter = 0.0;
  ViewerOptions o;
  o.width = 640;
  o.height = 400;
  o.frames = frames;
  o.ground = false;
  o.screenshot = file.string();
  o.before_frame = before_frame;
  Shot s;
  s.stats = run_lod_viewer(scene, lod, o);
  s.image = read_image(o.screenshot);
  return s;
}

// Pixels other than the sky's colour (the top-left corner's).
std::vector<bool> silhouette(const Image& image) {
  const auto* sky = image.pixel(0, 0);
  std::vector<bool> mask;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      mask.push_back(std::abs(p[0] - sky[0]) + std::abs(p[1] - sky[1]) + std::abs(p[2] - sky[2]) >
                     6);
    }
  }
  return mask;
}

double iou(const std::vector<bool>& a, const std::vector<bool>& b) {
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    both += a[i] && b[i] ? 1 : 0;
    either += a[i] || b[i] ? 1 : 0;
  }
  return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
}

double psnr_db(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = static_cast<double>(a.rgba[i]) - static_cast<double>(b.rgba[i]);
    sum += d * d;
  }
  const double mse = sum / (0.75 * static_cast<double>(a.rgba.size()));
  return 10.0 * std::log10(255.0 * 255.0 / std::max(mse, 1e-12));
}

// Mean colour of the silhouette's pixels.
Eigen::Vector3d mean_color(const Image& image, const std::vector<bool>& mask) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for (int i = 0; i < image.width * image.height; ++i) {
    if (!mask[static_cast<std::size_t>(i)]) continue;
    const auto* p = &image.rgba[4 * static_cast<std::size_t>(i)];
    sum += Eigen::Vector3d(p[0], p[1], p[2]);
    ++n;
  }
  return n == 0 ? sum : Eigen::Vector3d(sum / static_cast<double>(n));
}

std::size_t count(const std::vector<bool>& mask) {
  return static_cast<std::size_t>(std::count(mask.begin(), mask.end(), true));
}

TEST(ViewerImpostors, AsCloseToFullDetailAsTheSamePlantsTurnedBy15Degrees) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir = fs::temp_directory_path() / ("fspm_impostor_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const LodScene scene = grid_scene(0.0);
  const Shot full = view(scene, 0.0, 1, dir / "full.png");
  const Shot impostors = view(scene, 1e-3, 1, dir / "impostors.png");
  const Shot turned = view(grid_scene(kTurnDeg), 0.0, 1, dir / "turned.png");
  EXPECT_EQ(full.stats.impostors, 0u);
  EXPECT_EQ(impostors.stats.impostors, 16u);
  EXPECT_EQ(impostors.stats.triangles, 32u + 4u);  // two per quad, the four specks
  const auto a = silhouette(full.image), b = silhouette(impostors.image),
             c = silhouette(turned.image);
  ASSERT_GT(count(a), 2000u);  // the plants are there, some 40 pixels high
  const double iou_impostors = iou(a, b), iou_turned = iou(a, c);
  const double psnr_impostors = psnr_db(full.image, impostors.image),
               psnr_turned = psnr_db(full.image, turned.image);
  EXPECT_LT(iou_turned, 0.9);  // the oracle: a small turn changes many pixels
  EXPECT_GE(iou_impostors, 0.85 * iou_turned) << iou_impostors << " vs " << iou_turned;
  EXPECT_GE(psnr_impostors, psnr_turned - 1.0) << psnr_impostors << " vs " << psnr_turned;
  // As many plant pixels, in the same colours (the views keep normals, so each plant is lit as
  // it is turned).
  EXPECT_NEAR(static_cast<double>(count(b)) / static_cast<double>(count(a)), 1.0, 0.15);
  const Eigen::Vector3d ca = mean_color(full.image, a), cb = mean_color(impostors.image, b);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(cb[k] / ca[k], 1.0, 0.08) << "channel " << k;
  fs::remove_all(dir);
}

// The shadow map is drawn in the first frame and reused while its casters stay the same. When
// the panel's level-of-detail distance turns the impostors into meshes at the third frame, it is
// drawn again: the image is the one a viewer started with meshes everywhere shows.
TEST(ViewerImpostors, ShadowMapFollowsTheCasters) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir = fs::temp_directory_path() / ("fspm_shadow_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const LodScene scene = grid_scene(0.0, true);
  const Shot impostors = view(scene, 1e-3, 1, dir / "impostors.png");
  const Shot meshes = view(scene, 0.0, 1, dir / "meshes.png");
  const Shot switched =
      view(scene, 1e-3, 3, dir / "switched.png", [](int frame, ViewerControls& c) {
        if (frame == 2) c.lod_distance_m = 1e6;
      });
  EXPECT_EQ(impostors.stats.impostors, 16u);
  EXPECT_EQ(switched.stats.impostors, 0u);
  EXPECT_NE(impostors.image.rgba, meshes.image.rgba);  // the casters' shadows differ
  EXPECT_EQ(switched.image.rgba, meshes.image.rgba);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fspm::graphics
