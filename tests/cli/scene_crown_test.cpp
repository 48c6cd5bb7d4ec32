// Crowns reconstructed from a photograph placed in a scene file like any plant (Argudo ch. 5):
// the render shows each crown where its bounding box, placed and projected by hand, says.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "graphics/image.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;
using testing::run_fspm;
using testing::scratch_dir;
using testing::write_text;

const std::string kPhoto = std::string(FSPM_SOURCE_DIR) + "/examples/crown/tree_front.png";

bool skipped(const testing::CommandResult& r) {
  return r.exit_code != 0 && (r.err.find("without") != std::string::npos ||
                              r.err.find("no X display") != std::string::npos);
}

// Bounding box of the "v x y z" lines of an .obj, read here without the library.
void obj_bounds(const fs::path& path, Eigen::Vector3d& lo, Eigen::Vector3d& hi) {
  lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    Eigen::Vector3d v;
    s >> v.x() >> v.y() >> v.z();
    lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  }
}

struct Rect {
  double left, right, top, bottom;  // pixel columns and rows
};

// Foreground: a pixel away from the background's vertical gradient, which column 0 shows.
bool foreground(const graphics::Image& im, int x, int y) {
  const auto *p = im.pixel(x, y), *b = im.pixel(0, y);
  return std::abs(p[0] - b[0]) + std::abs(p[1] - b[1]) + std::abs(p[2] - b[2]) > 30;
}

// The bounding rectangle of the foreground pixels in columns [x0, x1).
Rect drawn(const graphics::Image& im, int x0, int x1) {
  Rect r{1e9, -1e9, 1e9, -1e9};
  for (int y = 0; y < im.height; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (!foreground(im, x, y)) continue;
      r.left = std::min<double>(r.left, x), r.right = std::max<double>(r.right, x + 1);
      r.top = std::min<double>(r.top, y), r.bottom = std::max<double>(r.bottom, y + 1);
    }
  }
  return r;
}

TEST(SceneCrown, RenderPlacesEachCrownWhereItsProjectedBoxSays) {
  const auto dir = scratch_dir("scene_crown");
  auto r = run_fspm("crown " + kPhoto + " --image-height-m 8 -o " + (dir / "oak").string() + "/");
  if (skipped(r)) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("crown " + kPhoto + " --image-height-m 8 -o " + (dir / "oak.obj").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Eigen::Vector3d lo, hi;
  obj_bounds(dir / "oak.obj", lo, hi);
  ASSERT_GT(hi.z() - lo.z(), 1.0);
  // The directory crown as it is at (-6, 0, 0); the .obj turned 90 degrees about z (x <- -y) and
  // halved at (5, 2, 1).
  write_text(dir / "s.json", R"({"fspm_scene": 2, "plants": [
    {"crown": "oak", "position": [-6, 0, 0]},
    {"crown": "oak.obj", "position": [5, 2, 1], "rotation_deg": 90, "scale": 0.5}]})");
  const double ax0 = -6 + lo.x(), ax1 = -6 + hi.x(), az0 = lo.z(), az1 = hi.z();
  const double bx0 = 5 - 0.5 * hi.y(), bx1 = 5 - 0.5 * lo.y();
  const double bz0 = 1 + 0.5 * lo.z(), bz1 = 1 + 0.5 * hi.z();
  // Parallel projection of --view front (looking along +y, x to the right, z up) centred on the
  // scene's bounding box, the image 16 m high.
  const int w = 400, h = 200;
  const double ortho_m = 16.0, px_per_m = h / ortho_m;
  const double cx = 0.5 * (std::min(ax0, bx0) + std::max(ax1, bx1));
  const double cz = 0.5 * (std::min(az0, bz0) + std::max(az1, bz1));
  auto project = [&](double x0, double x1, double z0, double z1) {
    return Rect{0.5 * w + (x0 - cx) * px_per_m, 0.5 * w + (x1 - cx) * px_per_m,
                0.5 * h - (z1 - cz) * px_per_m, 0.5 * h - (z0 - cz) * px_per_m};
  };
  const Rect a = project(ax0, ax1, az0, az1), b = project(bx0, bx1, bz0, bz1);
  ASSERT_LT(a.right + 4, b.left);  // apart, and inside the picture
  ASSERT_GT(a.left, 4.0);
  ASSERT_LT(b.right, w - 4.0);
  r = run_fspm("render " + (dir / "s.json").string() + " -o " + (dir / "s.png").string() +
               " --view front --size 400x200 --no-ground --ortho-height 16");
  if (skipped(r)) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const graphics::Image im = graphics::read_image((dir / "s.png").string());
  const int split = static_cast<int>(0.5 * (a.right + b.left));
  for (const auto& [got, want] : {std::pair{drawn(im, 1, split), a}, {drawn(im, split, w), b}}) {
    EXPECT_NEAR(got.left, want.left, 2.0);
    EXPECT_NEAR(got.right, want.right, 2.0);
    EXPECT_NEAR(got.top, want.top, 2.0);
    EXPECT_NEAR(got.bottom, want.bottom, 2.0);
  }
}

TEST(SceneCrown, MissingCrownIsRefusedWithFileAndLine) {
  const auto dir = scratch_dir("scene_crown_bad");
  write_text(dir / "bad.json",
             "{\"fspm_scene\": 2, \"plants\": [\n  {\"file\": \"t.tree\"},\n"
             "  {\"crown\": \"no_such_crown\", \"position\": [1, 0, 0]}]}\n");
  auto r = run_fspm("render " + (dir / "bad.json").string() + " -o " + (dir / "bad.png").string() +
                    " --view front --size 100x100");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.json:3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("/plants/1/crown"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  write_text(dir / "bad2.json", R"({"plants": [{"crown": "bad2.json"}]})");
  r = run_fspm("mesh " + (dir / "bad2.json").string() + " -o " + (dir / "m.obj").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad2.json:1:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("neither a .glb, .gltf or .obj mesh"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "bad.png"));
}

}  // namespace
}  // namespace fspm
