// fspm render of the stages of encoding a scan: a point set as spheres, a .clusters model as
// skeleton and hulls, and --frame, which aims the camera at another file's bounds.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "fspm/tree_file.hpp"
#include "graphics/image.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

// Mean column of the dark (bark-coloured) pixels against the light sky, and their count.
struct DarkPixels {
  std::size_t count = 0;
  double mean_x = 0.0;
};

DarkPixels dark_pixels(const graphics::Image& image) {
  DarkPixels d;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (p[0] + p[1] + p[2] < 400) {
        ++d.count;
        d.mean_x += x;
      }
    }
  }
  if (d.count > 0) d.mean_x /= static_cast<double>(d.count);
  return d;
}

void write_xyz(const std::filesystem::path& path, const std::vector<Eigen::Vector3d>& points) {
  std::ofstream out(path);
  for (const auto& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
}

TEST(ScanRenderCli, PointsAreSpheresFramedByAnotherFile) {
  const auto dir = scratch_dir("scan_render_points");
  // A column of 11 points 0.1 m high and one point 10 m above: the set's extent is 10 m, so each
  // sphere has radius 0.002 * 10 m = 2 cm, 8 pixels across at 200 pixels per metre.
  std::vector<Eigen::Vector3d> column;
  for (int i = 0; i <= 10; ++i) column.emplace_back(0.0, 0.0, 0.01 * i);
  column.emplace_back(0.0, 0.0, 10.0);
  write_xyz(dir / "points.xyz", column);
  // Two frames of the same height: centred on the column, and 0.25 m to one side of it.
  write_xyz(dir / "centred.xyz", {{-0.5, 0.0, 0.0}, {0.5, 0.0, 0.1}});
  write_xyz(dir / "aside.xyz", {{-1.0, 0.0, 0.0}, {0.5, 0.0, 0.1}});
  const std::string common = " --view front --size 200x200 --ortho-height 1 --no-ground --json";
  const std::string points = (dir / "points.xyz").string();
  auto r = run_fspm("render " + points + " -o " + (dir / "a.png").string() + common + " --frame " +
                    (dir / "centred.xyz").string());
  if (r.err.find("without VTK") != std::string::npos) GTEST_SKIP() << "built without VTK";
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A UV sphere of 6 meridians and 3 parallels: 6 triangles in each pole row, 12 in the middle.
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], 12 * 24);
  r = run_fspm("render " + points + " -o " + (dir / "b.png").string() + common + " --frame " +
               (dir / "aside.xyz").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("render " + points + " -o " + (dir / "c.png").string() + common);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const DarkPixels a = dark_pixels(graphics::read_image((dir / "a.png").string()));
  const DarkPixels b = dark_pixels(graphics::read_image((dir / "b.png").string()));
  const DarkPixels c = dark_pixels(graphics::read_image((dir / "c.png").string()));
  // The column: about 8 x 28 pixels, in the middle of the centred frame.
  EXPECT_GT(a.count, 100u);
  EXPECT_LT(a.count, 600u);
  EXPECT_NEAR(a.mean_x, 100.0, 3.0);
  // The same column 0.25 m * 200 px/m = 50 px off the middle in the other frame.
  EXPECT_EQ(b.count, a.count);
  EXPECT_NEAR(std::abs(b.mean_x - a.mean_x), 50.0, 3.0);
  // Without --frame the camera centres the whole set (5 m up): the column is out of view.
  EXPECT_LT(c.count, a.count / 2);
}

TEST(ScanRenderCli, ClustersDrawSkeletonAndHulls) {
  const auto dir = scratch_dir("scan_render_clusters");
  const std::string tree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  const std::string model = (dir / "tree.clusters").string();
  const std::string skeleton = (dir / "skeleton.tree").string();
  auto r = run_fspm("encode " + tree + " --seed 1 --root-diameter 0.075 --fs 3 -o " + model +
                    " --skeleton " + skeleton + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_GT(nlohmann::json::parse(r.out)["clusters"].get<int>(), 0);
  const std::string common = " --size 160x120 --json";
  r = run_fspm("render " + skeleton + " -o " + (dir / "s.png").string() + common);
  if (r.err.find("without VTK") != std::string::npos) GTEST_SKIP() << "built without VTK";
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto bare = nlohmann::json::parse(r.out)["triangles"].get<std::size_t>();
  r = run_fspm("render " + model + " -o " + (dir / "m.png").string() + common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The same skeleton tubes plus the hulls' triangles.
  EXPECT_GT(nlohmann::json::parse(r.out)["triangles"].get<std::size_t>(), bare + 50);

  r = run_fspm("render " + model + " -o " + (dir / "x.png").string() + " --frame " +
               (dir / "missing.ply").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// A skeleton at projected coordinates (as fspm encode --skeleton writes one for a GIS cloud) is
// drawn without the ground as it is at the origin: the same tree, the same pixels.
TEST(ScanRenderCli, TreeAtProjectedCoordinatesIsFramedWithoutGround) {
  const auto dir = scratch_dir("scan_render_projected_tree");
  const auto y_tree = [](const Eigen::Vector3d& at) {
    TreeGraph t;
    NodeData d;
    d.radius = 0.15;
    d.start = at, d.end = at + Eigen::Vector3d(0, 0, 3);
    const NodeId trunk = t.add_node(kNoNode, d);
    d.radius = 0.08, d.order = 1;
    for (double side : {-1.0, 1.0}) {
      d.start = at + Eigen::Vector3d(0, 0, 3), d.end = at + Eigen::Vector3d(1.5 * side, 0, 5);
      t.add_node(trunk, d);
    }
    return t;
  };
  write_tree_file(y_tree(Eigen::Vector3d::Zero()), (dir / "origin.tree").string());
  write_tree_file(y_tree({500123.4, 5800456.7, 312.3}), (dir / "projected.tree").string());
  const std::string common = " --view front --size 200x200 --no-ground --json";
  auto r = run_fspm("render " + (dir / "origin.tree").string() + " -o " +
                    (dir / "origin.png").string() + common);
  if (r.err.find("without VTK") != std::string::npos) GTEST_SKIP() << "built without VTK";
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("render " + (dir / "projected.tree").string() + " -o " +
               (dir / "projected.png").string() + common);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const DarkPixels origin = dark_pixels(graphics::read_image((dir / "origin.png").string()));
  const DarkPixels projected = dark_pixels(graphics::read_image((dir / "projected.png").string()));
  // The Y, 3 m wide and 5 m high, fills a good part of the picture in both.
  EXPECT_GT(origin.count, 1000u);
  EXPECT_GT(projected.count, origin.count * 9 / 10);
  EXPECT_LT(projected.count, origin.count * 11 / 10);
  EXPECT_NEAR(projected.mean_x, origin.mean_x, 3.0);
}

}  // namespace
}  // namespace fspm
