// A crown is one closed volume: seen from any direction its silhouette is a region without holes
// (a pierced silhouette would show the sky through the crown, a "tyre"). The crown of the example
// photograph, made as `fspm crown` makes it (automatic mask, gaps filled, default options), is
// projected in parallel along 8 directions (front, back, both sides, top, bottom and two oblique
// ones) onto a 256 x 256 grid, and the background is flooded from the grid's border: every pixel
// the flood does not reach must be covered by the crown. The check itself is checked on a ring
// mask, whose inflated crown is a torus with a hole seen from the front.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "crown/auto_mask.hpp"
#include "crown/crown_from_photo.hpp"
#include "crown/image_io.hpp"

namespace fspm::crown {
namespace {

constexpr int kGrid = 256;

// The crown triangles projected along `view` onto a kGrid x kGrid grid framing them, as a
// covered/uncovered raster (pixel centres inside a triangle, edges included, so neighbouring
// triangles leave no crack).
std::vector<std::uint8_t> silhouette(const CrownMesh& mesh, const Eigen::Vector3d& view) {
  const Eigen::Vector3d d = view.normalized();
  const Eigen::Vector3d u = d.unitOrthogonal(), v = d.cross(u);
  std::vector<Eigen::Vector2d> q;
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const auto& p : mesh.positions) {
    q.emplace_back(p.cast<double>().dot(u), p.cast<double>().dot(v));
    lo = lo.cwiseMin(q.back()), hi = hi.cwiseMax(q.back());
  }
  const double scale = (kGrid - 8) / (hi - lo).maxCoeff();  // a 4-pixel margin of background
  for (auto& p : q) p = (p - lo) * scale + Eigen::Vector2d(4, 4);
  std::vector<std::uint8_t> covered(kGrid * kGrid, 0);
  auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
    return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
  };
  for (std::size_t t = 0; t < mesh.crown_triangles; ++t) {
    const Eigen::Vector2d a = q[mesh.triangles[t][0]], b = q[mesh.triangles[t][1]],
                          c = q[mesh.triangles[t][2]];
    const double area = cross(a, b, c);
    if (area == 0.0) continue;
    const double s = area > 0.0 ? 1.0 : -1.0;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
    const int x1 =
        std::min(kGrid - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
    const int y1 =
        std::min(kGrid - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2d p(x + 0.5, y + 0.5);
        if (s * cross(a, b, p) >= 0 && s * cross(b, c, p) >= 0 && s * cross(c, a, p) >= 0) {
          covered[static_cast<std::size_t>(y * kGrid + x)] = 1;
        }
      }
    }
  }
  return covered;
}

// Uncovered pixels the background flood (4-neighbours, from the grid's border) does not reach.
std::size_t hole_pixels(const std::vector<std::uint8_t>& covered) {
  std::vector<std::uint8_t> reached(covered.size(), 0);
  std::vector<int> stack;
  for (int i = 0; i < kGrid; ++i) {
    for (int p : {i, (kGrid - 1) * kGrid + i, i * kGrid, i * kGrid + kGrid - 1}) {
      if (!covered[static_cast<std::size_t>(p)] && !reached[static_cast<std::size_t>(p)]) {
        reached[static_cast<std::size_t>(p)] = 1;
        stack.push_back(p);
      }
    }
  }
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    const int x = p % kGrid, y = p / kGrid;
    for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int qx = x + dx, qy = y + dy;
      if (qx < 0 || qy < 0 || qx >= kGrid || qy >= kGrid) continue;
      const auto q = static_cast<std::size_t>(qy * kGrid + qx);
      if (covered[q] || reached[q]) continue;
      reached[q] = 1;
      stack.push_back(static_cast<int>(q));
    }
  }
  std::size_t holes = 0;
  for (std::size_t p = 0; p < covered.size(); ++p) holes += !covered[p] && !reached[p];
  return holes;
}

const std::array<Eigen::Vector3d, 8> kViews = {
    Eigen::Vector3d(0, 1, 0),  Eigen::Vector3d(0, -1, 0),   Eigen::Vector3d(1, 0, 0),
    Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, 0, 1),    Eigen::Vector3d(0, 0, -1),
    Eigen::Vector3d(1, 1, 1),  Eigen::Vector3d(-1, 1, -0.5)};

TEST(ClosedCrown, ExamplePhotographCrownHasNoHoleFromAnyOfEightDirections) {
  const Raster photo = read_rgb(std::string(FSPM_SOURCE_DIR) + "/examples/crown/tree_front.png");
  const Mask mask = auto_mask(photo, {});
  const Mask foliage = foreground(photo, AutoMaskOptions{}.threshold);
  std::mt19937_64 rng(1);
  const CrownModel model = reconstruct_crown(photo, mask, {}, rng, &foliage);
  for (const auto& view : kViews) {
    const auto covered = silhouette(model.mesh, view);
    const auto area = std::count(covered.begin(), covered.end(), 1);
    const std::size_t holes = hole_pixels(covered);
    std::cout << "view (" << view.transpose() << "): " << area << " pixels, " << holes
              << " in holes\n";
    EXPECT_GT(area, kGrid * kGrid / 8);  // the crown is there, framed
    EXPECT_EQ(holes, 0u) << "view (" << view.transpose() << ")";
  }
}

// A ring of crown inflates to a torus: from the front its hole shows, and the check finds it.
TEST(ClosedCrown, TheCheckFindsTheHoleOfARing) {
  Mask ring(128, 128);
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 128; ++x) {
      const double r = std::hypot(x - 63.5, y - 63.5);
      ring.set(x, y, r > 25.0 && r < 55.0);
    }
  }
  const Raster photo(128, 128, 3, 0.3f);
  std::mt19937_64 rng(1);
  const CrownModel model = reconstruct_crown(photo, ring, {}, rng);
  EXPECT_GT(hole_pixels(silhouette(model.mesh, Eigen::Vector3d(0, 1, 0))), 1000u);
}

}  // namespace
}  // namespace fspm::crown
