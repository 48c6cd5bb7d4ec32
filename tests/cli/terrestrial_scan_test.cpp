// fspm encode of a real terrestrial scan (examples/scans/tls_lodgepole_pine.las, a pine cut out
// of a TLS plot), checked against the cloud itself: its height against the LAS header's z range,
// its DBH against a circle this test fits to the points 1.2-1.4 m above the lowest one, and its
// skeleton against the stem's position and the crown's extent.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

const std::string kPine = std::string(FSPM_SOURCE_DIR) + "/examples/scans/tls_lodgepole_pine.las";

template <typename T>
T field(const std::vector<char>& bytes, std::size_t at) {
  T v{};
  std::memcpy(&v, bytes.data() + at, sizeof(T));
  return v;
}

// The points of an uncompressed LAS 1.2 file, read here from the specification's byte offsets
// (ASPRS LAS 1.2: offset to the points at 96, record length at 105, count at 107, scales at 131,
// offsets at 155; x, y, z as int32 at the start of every record), not by fspm's reader.
std::vector<Eigen::Vector3d> las_points(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto first = field<std::uint32_t>(b, 96);
  const auto length = field<std::uint16_t>(b, 105);
  const auto count = field<std::uint32_t>(b, 107);
  const Eigen::Vector3d scale(field<double>(b, 131), field<double>(b, 139), field<double>(b, 147));
  const Eigen::Vector3d offset(field<double>(b, 155), field<double>(b, 163), field<double>(b, 171));
  std::vector<Eigen::Vector3d> out;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::size_t at = first + static_cast<std::size_t>(i) * length;
    const Eigen::Vector3d raw(field<std::int32_t>(b, at), field<std::int32_t>(b, at + 4),
                              field<std::int32_t>(b, at + 8));
    out.push_back(offset + raw.cwiseProduct(scale));
  }
  return out;
}

struct Circle2 {
  Eigen::Vector2d centre;
  double radius = 0.0;
};

// Geometric least-squares circle (Gauss-Newton on the distances to the circle, started from the
// centroid and the mean distance to it), a different fit from fspm's algebraic one (Kasa 1976).
Circle2 fit_circle_geometric(const std::vector<Eigen::Vector2d>& xy) {
  Circle2 c;
  for (const Eigen::Vector2d& p : xy) c.centre += p / static_cast<double>(xy.size());
  for (const Eigen::Vector2d& p : xy) c.radius += (p - c.centre).norm() / xy.size();
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (const Eigen::Vector2d& p : xy) {
      const Eigen::Vector2d d = p - c.centre;
      const double n = d.norm();
      const Eigen::Vector3d j(-d.x() / n, -d.y() / n, -1.0);  // d(n - r)/d(cx, cy, r)
      jtj += j * j.transpose();
      jtr += j * (n - c.radius);
    }
    const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
    c.centre += step.head<2>();
    c.radius += step.z();
    if (step.norm() < 1e-9) break;
  }
  return c;
}

// Height from the header's z range, DBH within 5 % of the circle the breast-height points give
// (the file's coordinates are whole centimetres, 119 points about a 7.5 cm radius, a few of them
// inside the ring: this plain geometric fit gives 0.144 m, one that down-weights the inner
// points 0.150 m),
// no warning about the stem, the default main skeleton up the stem (within 5 cm of that circle's
// centre at 1.3 m) to the top (95 % of the height) and across 85 % of the crown's extent.
TEST(TerrestrialScan, PineIsMeasuredAgainstItsOwnPoints) {
  const auto dir = scratch_dir("tls_pine");
  const std::vector<Eigen::Vector3d> points = las_points(kPine);
  ASSERT_GT(points.size(), 30000u);
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (const Eigen::Vector3d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  std::vector<Eigen::Vector2d> slice;
  for (const Eigen::Vector3d& p : points) {
    if (p.z() >= lo.z() + 1.2 && p.z() <= lo.z() + 1.4) slice.push_back(p.head<2>());
  }
  ASSERT_GT(slice.size(), 50u);
  const Circle2 stem = fit_circle_geometric(slice);
  ASSERT_GT(stem.radius, 0.05);  // a pole-sized pine: about 0.15 m across
  ASSERT_LT(stem.radius, 0.10);

  const std::string main = (dir / "main.tree").string();
  const auto r = run_fspm("encode " + kPine + " -o " + (dir / "p.clusters").string() +
                          " --skeleton " + main + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["height_m"].get<double>(), hi.z() - lo.z(), 0.01);
  ASSERT_TRUE(j["dbh_m"].is_number()) << r.err;
  EXPECT_NEAR(j["dbh_m"].get<double>(), 2.0 * stem.radius, 0.05 * 2.0 * stem.radius);
  EXPECT_EQ(j["stems"], 1);
  EXPECT_EQ(r.err.find("trunk"), std::string::npos) << r.err;

  const TreeGraph t = read_tree_file(main);
  Eigen::Vector3d tlo = Eigen::Vector3d::Constant(1e300), thi = -tlo;
  bool crossed = false;
  for (NodeId n = 0; n < t.size(); ++n) {
    const Eigen::Vector3d a = t.start(n), b = t.end(n);
    tlo = tlo.cwiseMin(a).cwiseMin(b), thi = thi.cwiseMax(a).cwiseMax(b);
    const double at = lo.z() + 1.3;
    if (t.order(n) == 0 && (a.z() - at) * (b.z() - at) <= 0.0 && a.z() != b.z()) {
      const Eigen::Vector3d x = a + (at - a.z()) / (b.z() - a.z()) * (b - a);
      EXPECT_LT((x.head<2>() - stem.centre).norm(), 0.05);
      crossed = true;
    }
  }
  EXPECT_TRUE(crossed);
  EXPECT_GE(thi.z() - lo.z(), 0.95 * (hi.z() - lo.z()));
  EXPECT_GE(thi.x() - tlo.x(), 0.85 * (hi.x() - lo.x()));
  EXPECT_GE(thi.y() - tlo.y(), 0.85 * (hi.y() - lo.y()));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fspm
