// Variance shadow maps in the viewer: the ground where a tree's shadow falls, found from the sun's
// direction by hand, is darker with shadows on than off; ground far from it is the same.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "graphics/image.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

// A "T" tree: a trunk up z to 2 m and a horizontal bough along y from -1 to 1 m at its top, all
// 0.12 m thick.
TreeGraph t_tree() {
  TreeGraph t;
  const NodeId trunk = testing::add(t, kNoNode, {0, 0, 0}, {0, 0, 2}, 0.12, 0, 0);
  for (int side = -1; side <= 1; side += 2) {
    testing::add(t, trunk, {0, 0, 2}, {0, side * 1.0, 2}, 0.12, 1, 1);
  }
  return t;
}

// The pixel of world point `p` for a camera looking at `target` from `distance` m at `yaw` and
// `pitch` (radians), as the viewer places it (viewer.hpp: vertical field of view 40 degrees).
Eigen::Vector2d pixel_from(const Eigen::Vector3d& p, const Eigen::Vector3d& target, double distance,
                           double yaw, double pitch, int width, int height) {
  const double pi = 3.141592653589793;
  const Eigen::Vector3d eye =
      target + distance * Eigen::Vector3d(std::cos(pitch) * std::cos(yaw),
                                          std::cos(pitch) * std::sin(yaw), std::sin(pitch));
  const Eigen::Vector3d forward = (target - eye).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const Eigen::Vector3d v = p - eye;
  const double t = std::tan(20.0 * pi / 180.0);
  const double x_ndc = right.dot(v) / (forward.dot(v) * t * width / height);
  const double y_ndc = up.dot(v) / (forward.dot(v) * t);
  return {(x_ndc + 1.0) * 0.5 * width, (1.0 - y_ndc) * 0.5 * height};
}

// The pixel of world point `p` in the viewer's first frame: the camera looks at the centre of
// the bounds from yaw -0.9 rad and `pitch_deg`, 2.6 bounding radii away.
Eigen::Vector2d pixel_of(const Eigen::Vector3d& p, const Eigen::Vector3d& lo,
                         const Eigen::Vector3d& hi, double pitch_deg, int width, int height) {
  const double distance = 2.6 * std::max(0.5 * (hi - lo).norm(), 0.1);
  return pixel_from(p, 0.5 * (lo + hi), distance, -0.9, pitch_deg * 3.141592653589793 / 180.0,
                    width, height);
}

TEST(ViewerShadow, GroundUnderTheTreeIsDarkerWithShadows) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir =
      fs::temp_directory_path() / ("fspm_viewer_vsm_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // Unused vertices at (+-3, +-3, 0) widen the bounds (so the camera frames the ground around the
  // tree) without moving the ground, the plane z = 0 under the trunk.
  TriangleMesh mesh = mesh_tree(t_tree(), {});
  TriangleMesh corners;
  for (int k = 0; k < 4; ++k) {
    corners.positions.emplace_back(k & 1 ? 3.0f : -3.0f, k & 2 ? 3.0f : -3.0f, 0.0f);
    corners.normals.emplace_back(0, 0, 1);
    corners.uvs.emplace_back(0, 0);
  }
  mesh.append(corners);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
  for (const auto& p : mesh.positions) {
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  ViewerOptions o;
  o.width = 400;
  o.height = 300;
  o.pitch_deg = 20.0;  // low enough to see the ground behind the tree from the sun
  o.screenshot = (dir / "on.png").string();
  (void)run_viewer({mesh}, {0.0}, o);
  o.shadows = false;
  o.screenshot = (dir / "off.png").string();
  (void)run_viewer({mesh}, {0.0}, o);
  const Image on = read_image((dir / "on.png").string());
  const Image off = read_image((dir / "off.png").string());
  // The sun is along (0.5, -0.4, 1) (viewer_glfw.cpp): a point h above the ground casts its shadow
  // h (0.5, -0.4) away, at -h (0.5, -0.4). The bough's points (0, -0.9, 2) and (0, -0.6, 2) are 2 m
  // up: their shadows lie at (-1.0, -0.1) and (-1.0, 0.2) on the ground z = lo.z = 0. (The camera,
  // from yaw -0.9, looks along the shadows of the bough's other half and of the trunk: the trunk
  // hides them.) The rays from these two points to the eye rise tan 20 degrees per metre towards
  // (0.62, -0.78) and pass the bough's plane x = 0 at 0.6 m height: the tree hides neither.
  const double ground = lo.z();
  const double h = 2.0 - ground;
  for (const double y : {-0.9, -0.6}) {
    const Eigen::Vector3d shade(-0.5 * h, y + 0.4 * h, ground);
    const Eigen::Vector2d px = pixel_of(shade, lo, hi, o.pitch_deg, o.width, o.height);
    const int x = static_cast<int>(px.x()), r = static_cast<int>(px.y());
    ASSERT_TRUE(x >= 0 && x < o.width && r >= 0 && r < o.height) << x << "," << r;
    const auto* lit = off.pixel(x, r);
    const auto* dark = on.pixel(x, r);
    // Ground there in both (green above red and blue), not the tree in front of it.
    EXPECT_GT(lit[1], lit[2]);
    EXPECT_GT(lit[1], lit[0]);
    // Lit ground is shaded 0.35 + 0.65 cos(sun, up) = 0.897 of its colour, shadowed 0.35; after
    // the display gamma 1/1.2, 0.457 times as bright. Asked: well under 0.7 times.
    EXPECT_LT(dark[1], 0.7 * lit[1]) << "shadow of (0, " << y << ", 2) at pixel " << x << "," << r;
  }
  // Away from the shadows (those of the trunk and bough lie within x in [-1, 0], y in [-0.2, 1.8])
  // the ground is lit alike with shadows on or off.
  for (const Eigen::Vector3d& far :
       {Eigen::Vector3d(1.5, -1.5, ground), Eigen::Vector3d(-2.0, -1.0, ground)}) {
    const Eigen::Vector2d px = pixel_of(far, lo, hi, o.pitch_deg, o.width, o.height);
    const int x = static_cast<int>(px.x()), r = static_cast<int>(px.y());
    ASSERT_TRUE(x >= 0 && x < o.width && r >= 0 && r < o.height) << x << "," << r;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(on.pixel(x, r)[k], off.pixel(x, r)[k]) << x << "," << r;
  }
  fs::remove_all(dir);
}

// The T tree in a scene 800 m wide (unused vertices at +-400 m): the one map of the whole scene
// gives each texel about 2.4 m of ground, so the bough, 0.12 m thick, casts next to nothing; with
// three cascades the nearest map's texels are millimetres and its shadow is as dark as in a small
// scene. The camera looks at the tree from 8 m; the shadow's place is found from the sun's
// direction by hand, as above.
TEST(ViewerShadow, CascadesResolveASmallTreesShadowInALargeScene) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir =
      fs::temp_directory_path() / ("fspm_viewer_cascades_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  TriangleMesh mesh = mesh_tree(t_tree(), {});
  TriangleMesh corners;
  for (int k = 0; k < 4; ++k) {
    corners.positions.emplace_back(k & 1 ? 400.0f : -400.0f, k & 2 ? 400.0f : -400.0f, 0.0f);
    corners.normals.emplace_back(0, 0, 1);
    corners.uvs.emplace_back(0, 0);
  }
  mesh.append(corners);
  ViewerOptions o;
  o.width = 400;
  o.height = 300;
  o.look_at = std::array<double, 3>{-0.5, -0.2, 0.8};
  o.camera_distance_m = 8.0;
  o.frames = 3;
  const auto shoot = [&](int cascades, bool shadows, const std::string& name) {
    o.shadow_cascades = cascades;
    o.shadows = shadows;
    o.screenshot = (dir / name).string();
    const ViewerStats stats = run_viewer({mesh}, {0.0}, o);
    return std::make_pair(read_image(o.screenshot), stats);
  };
  const auto [one_map, one_stats] = shoot(0, true, "one_map.png");
  const auto [cascaded, cascaded_stats] = shoot(3, true, "cascaded.png");
  const auto [off, off_stats] = shoot(3, false, "off.png");
  // The panel's cascades slider, moved from 0 to 3 before the third frame: new maps, drawn then,
  // and the picture of a viewer started with three cascades.
  o.before_frame = [](int frame, ViewerControls& c) {
    if (frame == 2) c.shadow_cascades = 3;
  };
  const auto [switched, switched_stats] = shoot(0, true, "switched.png");
  o.before_frame = nullptr;
  EXPECT_EQ(switched_stats.shadow_maps_drawn, 1u + 4u);
  EXPECT_EQ(switched_stats.controls.shadow_cascades, 3);
  EXPECT_EQ(switched.rgba, cascaded.rgba);
  // A still camera: every map is drawn in the first frame and reused by the next two.
  EXPECT_EQ(one_stats.shadow_maps_drawn, 1u);
  EXPECT_EQ(cascaded_stats.shadow_maps_drawn, 4u);
  EXPECT_EQ(off_stats.shadow_maps_drawn, 0u);
  const double pi = 3.141592653589793;
  const Eigen::Vector3d target(-0.5, -0.2, 0.8);
  for (const double y : {-0.9, -0.6}) {
    const Eigen::Vector3d shade(-1.0, y + 0.8, 0.0);  // of (0, y, 2), 2 m up: -2 (0.5, -0.4)
    const Eigen::Vector2d px =
        pixel_from(shade, target, 8.0, -0.9, o.pitch_deg * pi / 180.0, o.width, o.height);
    const int x = static_cast<int>(px.x()), r = static_cast<int>(px.y());
    ASSERT_TRUE(x >= 0 && x < o.width && r >= 0 && r < o.height) << x << "," << r;
    const auto* lit = off.pixel(x, r);
    EXPECT_GT(lit[1], lit[2]);  // ground, not the tree in front of it
    EXPECT_GT(lit[1], lit[0]);
    // As in the small scene: well under 0.7 times as bright with the cascades; the one map
    // leaves the ground nearly as lit (over 0.85 times).
    EXPECT_LT(cascaded.pixel(x, r)[1], 0.7 * lit[1]) << x << "," << r;
    EXPECT_GT(one_map.pixel(x, r)[1], 0.85 * lit[1]) << x << "," << r;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fspm::graphics
