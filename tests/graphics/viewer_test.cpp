#include "graphics/viewer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "fspm/error.hpp"
#include "graphics/image.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

TEST(Viewer, RejectsUnknownAttributeAndNoSteps) {
  ViewerOptions o;
  EXPECT_THROW(run_viewer({}, {}, o), ValueError);
  o.color_by = "nope";
  EXPECT_THROW(run_viewer({mesh_tree(testing::small_tree(), {})}, {0.0}, o), ValueError);
}

TEST(Viewer, ScreenshotAfterFramesShowsTreeAndShadow) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir = fs::temp_directory_path() / ("fspm_viewer_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  ViewerOptions o;
  o.width = 320;
  o.height = 240;
  o.frames = 3;
  o.screenshot = (dir / "shot.png").string();
  MeshOptions mo;
  mo.leaves = true;
  const TreeGraph tree = testing::small_tree();
  std::vector<TriangleMesh> steps;
  mo.max_birth_time = 2.5;
  steps.push_back(mesh_tree(tree, mo));
  mo.max_birth_time = 10;
  steps.push_back(mesh_tree(tree, mo));
  const ViewerStats stats = run_viewer(steps, {2.5, 10}, o);
  EXPECT_EQ(stats.frames, 3);
  EXPECT_EQ(stats.triangles, steps.back().triangle_count());  // starts on the last step
  EXPECT_GT(stats.mean_frame_ms, 0.0);
  const Image shot = read_image(o.screenshot);
  ASSERT_EQ(shot.width, 320);
  ASSERT_EQ(shot.height, 240);
  // Sky at the top-left corner; bark pixels (red > green > blue); ground pixels both lit
  // (0.55, 0.62, 0.45 shaded) and in shadow (same hue, darker).
  const auto* sky = shot.pixel(0, 0);
  EXPECT_GT(sky[2], sky[0]);
  std::size_t bark = 0, lit_ground = 0, dark_ground = 0;
  for (int y = 0; y < shot.height; ++y) {
    for (int x = 0; x < shot.width; ++x) {
      const auto* p = shot.pixel(x, y);
      if (p[0] > p[1] + 10 && p[1] > p[2] + 5) ++bark;
      const bool greenish_grey = p[1] > p[0] && p[1] > p[2] && p[1] - p[2] < 60;
      if (greenish_grey && p[1] > 130) ++lit_ground;
      if (greenish_grey && p[1] < 100 && p[1] > 20) ++dark_ground;
    }
  }
  EXPECT_GT(bark, 100u);
  EXPECT_GT(lit_ground, 1000u);
  EXPECT_GT(dark_ground, 20u);
  fs::remove_all(dir);
}

// The ground reaches the horizon. Seen from 3 degrees above the horizontal, the plane's points at
// infinity lie on the row where a horizontal ray meets the image: with the viewer's vertical field
// of view of 40 degrees, y_ndc = tan 3 / tan 20 = 0.1440, 0.856 H / 2 = 102.7 rows from the top of
// a 240-row image, whatever the eye's height. Below it, in every column, the pixels are ground
// (green above blue, the sky's colour mixed in at most half), above it the cleared sky (blue
// above green). A finite ground quad ends well below that row at this angle.
TEST(Viewer, LowViewShowsGroundUpToTheHorizon) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir =
      fs::temp_directory_path() / ("fspm_viewer_low_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // A post at the centre of bounds [-1.5, 1.5]^3 given by unused corner vertices: the ground is
  // the plane z = -1.5, the eye 2.6 x 2.6 m from the centre.
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k) {
    mesh.positions.emplace_back(k & 1 ? 1.5f : -1.5f, k & 2 ? 1.5f : -1.5f, k & 4 ? 1.5f : -1.5f);
    mesh.normals.emplace_back(0, 0, 1);
    mesh.uvs.emplace_back(0, 0);
  }
  ViewerOptions o;
  o.width = 320;
  o.height = 240;
  o.shadows = false;
  o.pitch_deg = 3.0;
  o.screenshot = (dir / "low.png").string();
  (void)run_viewer({mesh}, {0.0}, o);
  const Image shot = read_image(o.screenshot);
  ASSERT_EQ(shot.height, 240);
  const double pi = 3.141592653589793;
  const double horizon = (1.0 - std::tan(3.0 * pi / 180) / std::tan(20.0 * pi / 180)) * 120.0;
  ASSERT_NEAR(horizon, 102.7, 0.05);
  std::size_t ground = 0, sky = 0, wrong = 0;
  for (int x = 0; x < shot.width; ++x) {
    for (int y = 0; y < shot.height; ++y) {
      const auto* p = shot.pixel(x, y);
      if (y >= horizon + 1) {
        (p[1] > p[2] ? ground : wrong) += 1;
      } else if (y <= horizon - 2) {
        (p[2] > p[1] + 10 ? sky : wrong) += 1;
      }
    }
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(ground, 320u * (240 - 104));  // rows 104-239
  EXPECT_EQ(sky, 320u * 101);             // rows 0-100
  // Nearby ground keeps its own colour (green well above blue), hazed less than the horizon.
  const auto* near = shot.pixel(160, 239);
  const auto* far = shot.pixel(5, 104);
  EXPECT_GT(near[1] - near[2], far[1] - far[2]);
  fs::remove_all(dir);
}

// Blending in the viewer against closed-form "over" compositing. The viewer's camera looks at the
// centre of the bounds from yaw -0.9, 10 degrees below it (so that the sky, not the ground, is
// behind the squares and an opaque wall stands out from it); squares facing it are stacked on
// that line of sight. Every mesh carries the same unused corner vertices, so every screenshot has
// the same bounds, camera and ground, and pixels compare one to one. Drawing a surface of opacity a
// over a frame F gives a L + (1 - a) F, so with B the empty picture and X the picture of surface X
// alone, X = a_X L_X + (1 - a_X) B and:
//   a crown (C, a_c = 0.35) in front of an opaque wall (W):        CW = C + (1 - a_c) (W - B);
//   a translucent square (S, a_s = 0.8) in front of the crown:     SC = S + (1 - a_s) (C - B),
// whereas the crown drawn after the square (wrong order) gives C + (1 - a_c) (S - B), which
// differs by a_s a_c (L_s - L_c); a crown drawn opaque gives CW = C.
class ViewerBlending : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fspm_viewer_blend_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    const float yaw = -0.9f, pitch = kPitchDeg * 3.14159265f / 180.0f;
    toward_eye_ = Eigen::Vector3f(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                                  std::sin(pitch));
    right_ = Eigen::Vector3f::UnitZ().cross(toward_eye_).normalized();
    up_ = toward_eye_.cross(right_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The fixed bounds [-1.5, 1.5]^3 as eight vertices no triangle uses.
  static TriangleMesh corners() {
    TriangleMesh m;
    for (int k = 0; k < 8; ++k) {
      m.positions.emplace_back(k & 1 ? 1.5f : -1.5f, k & 2 ? 1.5f : -1.5f, k & 4 ? 1.5f : -1.5f);
      m.normals.emplace_back(0, 0, 1);
      m.uvs.emplace_back(0, 0);
    }
    return m;
  }

  // A square of half side 0.6 facing the eye, `offset` towards it from the centre.
  TriangleMesh square(float offset, Material material, float translucency = 0.0f) const {
    TriangleMesh m;
    const Eigen::Vector3f c = offset * toward_eye_;
    for (const auto& [u, v] : {std::pair{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}) {
      m.positions.push_back(c + 0.6f * (u * right_ + v * up_));
      m.normals.push_back(toward_eye_);
      m.uvs.emplace_back(u, v);
    }
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.materials = {material, material};
    if (material == Material::kTranslucentObstacle) {
      std::vector<float>& gamma = m.add_attribute("translucency");
      std::fill(gamma.begin(), gamma.end(), translucency);
    }
    return m;
  }

  Image shot(const std::vector<TriangleMesh>& parts) const {
    TriangleMesh mesh = corners();
    for (const TriangleMesh& part : parts) mesh.append(part);
    ViewerOptions o;
    o.width = 240;
    o.height = 180;
    o.shadows = false;
    o.pitch_deg = kPitchDeg;
    o.frames = 2;
    o.screenshot = (dir_ / "shot.png").string();
    (void)run_viewer({mesh}, {0.0}, o);
    return read_image(o.screenshot);
  }

  static constexpr float kPitchDeg = -10.0f;
  fs::path dir_;
  Eigen::Vector3f toward_eye_, right_, up_;
};

TEST_F(ViewerBlending, CrownsAreTranslucentAndBlendedBackToFront) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const TriangleMesh crown = square(-0.4f, Material::kCrown);
  const TriangleMesh wall = square(-1.0f, Material::kObstacle);
  // Opacity 0.8; its triangles come first in the mesh, so drawing in mesh order would be wrong.
  const TriangleMesh net = square(0.4f, Material::kTranslucentObstacle, 0.2f);
  const Image b = shot({}), c = shot({crown}), w = shot({wall}), s = shot({net});
  const Image cw = shot({crown, wall}), sc = shot({net, crown});
  const float a_c = kCrownOpacity, a_s = translucent_obstacle_opacity(0.2f);
  int checked = 0;
  double wall_shows = 0.0, order_matters = 0.0;
  for (int y = 80; y < 100; ++y) {
    for (int x = 110; x < 130; ++x) {
      for (int k = 0; k < 3; ++k) {
        const auto at = [&](const Image& image) { return double(image.pixel(x, y)[k]); };
        const double crown_over_wall = at(c) + (1 - a_c) * (at(w) - at(b));
        const double net_over_crown = at(s) + (1 - a_s) * (at(c) - at(b));
        const double crown_over_net = at(c) + (1 - a_c) * (at(s) - at(b));
        EXPECT_NEAR(at(cw), crown_over_wall, 3.0) << x << "," << y << " channel " << k;
        EXPECT_NEAR(at(sc), net_over_crown, 3.0) << x << "," << y << " channel " << k;
        wall_shows = std::max(wall_shows, std::abs(crown_over_wall - at(c)));
        order_matters = std::max(order_matters, std::abs(net_over_crown - crown_over_net));
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 1200);
  // The checks can fail: an opaque crown would hide the wall, a wrong order would be off by more.
  EXPECT_GT(wall_shows, 15.0);
  EXPECT_GT(order_matters, 12.0);
}

// The coarse meshes take over where their ring edge spans at most two pixels: the small tree
// (about 4 m across, seen from some 6 m at 240 pixels high, about 50 pixels per metre) keeps
// its fine mesh with coarse edges of 0.2 m (10 pixels) and takes the coarse one with edges of
// 1 mm (0.05 pixels); without an edge length the switch stays at 1.5 times the starting distance.
TEST(Viewer, CoarseMeshesWhereTheirEdgesSpanTwoPixels) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir = fs::temp_directory_path() / ("fspm_coarse_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  MeshOptions fine;
  fine.edge_length_m = 0.001;  // 16 sides everywhere
  MeshOptions coarse = fine;
  coarse.max_sides = coarse.min_sides = 3;
  const TreeGraph tree = testing::small_tree();
  const std::vector<TriangleMesh> steps = {mesh_tree(tree, fine)}, far = {mesh_tree(tree, coarse)};
  ASSERT_GT(steps[0].triangle_count(), 2 * far[0].triangle_count());
  ViewerOptions o;
  o.width = 320;
  o.height = 240;
  o.screenshot = (dir / "shot.png").string();
  const auto drawn = [&](double coarse_edge_m) {
    o.coarse_edge_m = coarse_edge_m;
    return run_viewer(steps, {0.0}, o, far).triangles;
  };
  EXPECT_EQ(drawn(0.0), steps[0].triangle_count());
  EXPECT_EQ(drawn(0.2), steps[0].triangle_count());
  EXPECT_EQ(drawn(0.001), far[0].triangle_count());
  fs::remove_all(dir);
}

// Reynolds' tessellation with curved PN triangles rounds a coarse branch: a trunk 0.5 m thick
// meshed with 4 sides comes out closer to the same trunk meshed with 32 sides (the round one)
// when tessellated, on the GPU or on the CPU, than as it is.
TEST(Viewer, TessellationRoundsACoarseBranch) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir = fs::temp_directory_path() / ("fspm_tess_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  TreeGraph trunk;
  testing::add(trunk, kNoNode, {0, 0, 0}, {0, 0, 3}, 0.5, 0, 0);
  MeshOptions square, round;
  square.min_sides = square.max_sides = 4;
  round.min_sides = round.max_sides = 32;
  const TriangleMesh coarse = mesh_tree(trunk, square), fine = mesh_tree(trunk, round);
  ViewerOptions o;
  o.width = 320;
  o.height = 240;
  o.frames = 2;
  o.ground = false;
  const auto shot = [&](const TriangleMesh& mesh, double level, bool on_cpu,
                        const std::string& name) {
    o.screenshot = (dir / name).string();
    o.tessellation_max_level = level;
    o.tessellation_on_cpu = on_cpu;
    const ViewerStats stats = run_viewer({mesh}, {0.0}, o);
    EXPECT_EQ(stats.tessellation, level > 0 ? (on_cpu ? "cpu" : "gpu") : "") << name;
    return read_image(o.screenshot);
  };
  const auto psnr = [](const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
      const double d = static_cast<double>(a.rgba[i]) - static_cast<double>(b.rgba[i]);
      sum += d * d;
    }
    return 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(a.rgba.size()) / sum);
  };
  const Image reference = shot(fine, 0.0, false, "round.png");
  const double as_is = psnr(shot(coarse, 0.0, false, "square.png"), reference);
  const double gpu = psnr(shot(coarse, 8.0, false, "gpu.png"), reference);
  const double cpu = psnr(shot(coarse, 8.0, true, "cpu.png"), reference);
  EXPECT_GT(gpu, as_is + 1.5) << gpu << " dB against " << as_is;
  EXPECT_GT(cpu, as_is + 1.5) << cpu << " dB against " << as_is;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fspm::graphics
