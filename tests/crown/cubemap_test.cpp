// Cubemap addressing, texture synthesis and the blue-noise billboard points.
#include "crown/cubemap.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <Eigen/Geometry>
#include <functional>
#include <limits>
#include <random>

#include "crown/billboard_cloud.hpp"
#include "crown/color_cubemap.hpp"
#include "crown/radius_cubemap.hpp"
#include "crown/texture_synthesis.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

TEST(Cubemap, EveryTexelDirectionFallsBackInItsTexel) {
  const int n = 16;
  for (int f = 0; f < kCubeFaces; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const CubeTexel t = direction_texel(texel_direction(f, x, y, n), n);
        EXPECT_EQ(t.face, f);
        EXPECT_EQ(t.x, x);
        EXPECT_EQ(t.y, y);
      }
    }
  }
}

TEST(Cubemap, FaceCentresPointAlongTheAxes) {
  const Eigen::Vector3f axes[kCubeFaces] = {-Eigen::Vector3f::UnitY(), Eigen::Vector3f::UnitX(),
                                            Eigen::Vector3f::UnitY(),  -Eigen::Vector3f::UnitX(),
                                            Eigen::Vector3f::UnitZ(),  -Eigen::Vector3f::UnitZ()};
  for (int f = 0; f < kCubeFaces; ++f) {
    EXPECT_GT(texel_direction(f, 7.5f, 7.5f, 16).dot(axes[f]), 0.9999f) << f;
  }
}

// Adjacent lateral faces meet: the last column of one and the first of the next look the same way.
TEST(Cubemap, LateralFacesFormAStripAroundTheCrown) {
  const int n = 32;
  for (int f = 0; f < 4; ++f) {
    const Eigen::Vector3f a = texel_direction(f, n - 0.5f, 10, n);
    const Eigen::Vector3f b = texel_direction((f + 1) % 4, -0.5f, 10, n);
    EXPECT_GT(a.dot(b), 0.99999f) << f;
  }
  // The top face's bottom row meets the front face's top row.
  EXPECT_GT(texel_direction(4, 5, n - 0.5f, n).dot(texel_direction(0, 5, -0.5f, n)), 0.99999f);
  EXPECT_GT(texel_direction(5, 5, -0.5f, n).dot(texel_direction(0, 5, n - 0.5f, n)), 0.99999f);
}

// A cube of side 2 about the centre, 12 triangles and 8 vertices, far coarser than the cubemap:
// every texel's radius is the distance along its direction to the cube, 1 / max |d_i|, which a
// splat of the vertices alone could not give.
TEST(RadiusCubemap, EveryTexelHoldsTheDistanceToTheSurfaceAlongItsDirection) {
  CrownMesh cube;
  for (int k = 0; k < 8; ++k) {
    cube.positions.emplace_back(k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f);
  }
  cube.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  cube.crown_triangles = cube.triangles.size();
  const int n = 32;
  const Cubemap r = radius_cubemap(cube, Eigen::Vector3f::Zero(), n);
  int exact = 0, total = 0;
  for (int f = 0; f < kCubeFaces; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const Eigen::Vector3f d =
            texel_direction(f, static_cast<float>(x), static_cast<float>(y), n);
        const float expected = 1.0f / d.cwiseAbs().maxCoeff();
        const float got = r.faces[static_cast<std::size_t>(f)].at(x, y);
        EXPECT_NEAR(got, expected, 0.05f) << f << " " << x << " " << y;
        exact += std::abs(got - expected) < 1e-4f;
        ++total;
      }
    }
  }
  EXPECT_GE(exact, total - 8);  // the corners' texels also hold a corner vertex, sqrt(3) away
}

TEST(TextureSynthesis, MinimumErrorCutMatchesBruteForce) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int rows = 6, cols = 4;
  std::vector<float> e(rows * cols);
  for (float& v : e) v = u(rng);
  float best = std::numeric_limits<float>::max();
  std::function<void(int, int, float)> walk = [&](int i, int j, float sum) {
    sum += e[i * cols + j];
    if (i == rows - 1) {
      best = std::min(best, sum);
      return;
    }
    for (int k = std::max(0, j - 1); k <= std::min(cols - 1, j + 1); ++k) walk(i + 1, k, sum);
  };
  for (int j = 0; j < cols; ++j) walk(0, j, 0.0f);
  const std::vector<int> cut = min_error_cut(e, rows, cols);
  float sum = 0.0f;
  for (int i = 0; i < rows; ++i) {
    sum += e[i * cols + cut[i]];
    if (i > 0) {
      EXPECT_LE(std::abs(cut[i] - cut[i - 1]), 1);
    }
  }
  EXPECT_NEAR(sum, best, 1e-5f);
}

// Only crown pixels (green) may appear in the texture, never the sky around it (red).
TEST(TextureSynthesis, TakesPixelsFromInsideTheCrownOnly) {
  Raster rgb(64, 64, 3);
  Mask mask(64, 64);
  std::mt19937_64 noise(5);
  std::uniform_real_distribution<float> u(0.2f, 0.8f);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      const bool crown = (x - 32) * (x - 32) + (y - 32) * (y - 32) < 28 * 28;
      mask.set(x, y, crown);
      rgb.at(x, y, 0) = crown ? 0.0f : 1.0f;
      rgb.at(x, y, 1) = crown ? u(noise) : 0.0f;
    }
  }
  std::mt19937_64 rng(1);
  const Cubemap cube = color_cubemap(rgb, mask, 32, {}, rng);
  for (const Raster& f : cube.faces) {
    for (int y = 0; y < f.height; ++y) {
      for (int x = 0; x < f.width; ++x) ASSERT_EQ(f.at(x, y, 0), 0.0f);
    }
  }
}

TEST(TextureSynthesis, TileableStripWrapsAround) {
  // A strip whose last `band` columns repeat its first ones wraps with no change at all.
  const int width = 40, band = 5;
  Raster strip(width + band, 3, 3);
  for (int x = 0; x < width + band; ++x) {
    for (int y = 0; y < 3; ++y) strip.at(x, y, 1) = static_cast<float>(x % width) / width;
  }
  const Raster out = tileable_strip(strip, band);
  ASSERT_EQ(out.width, width);
  for (int x = 0; x < width; ++x) EXPECT_FLOAT_EQ(out.at(x, 1, 1), strip.at(x, 1, 1));
}

TEST(BillboardCloud, AboutThreeHundredPointsInTheUnitBall) {
  std::mt19937_64 rng(11);
  const auto points = blue_noise_ball(rng);
  // 8 + 64 + 512 octree cells, each kept with probability about pi / 6 (Argudo: 320).
  EXPECT_GT(points.size(), 260u);
  EXPECT_LT(points.size(), 350u);
  for (const auto& p : points) EXPECT_LE(p.norm(), 1.0f);
}

// Face f of the strip is columns f N .. f N + N - 1 (the layout docs/crown.md describes).
TEST(Cubemap, StripFacesSideBySide) {
  const int n = 3;
  Raster strip(6 * n, n, 1);
  for (int x = 0; x < 6 * n; ++x) {
    for (int y = 0; y < n; ++y) strip.at(x, y) = static_cast<float>(100 * (x / n) + 10 * y + x % n);
  }
  const Cubemap c = cubemap_from_strip(strip);
  ASSERT_EQ(c.size, n);
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(c.faces[f].at(2, 1), 100.0f * f + 12.0f);
  }
  EXPECT_THROW(cubemap_from_strip(Raster(5 * n, n, 1)), ValueError);
}

// Argudo 5.2's inequality, checked for every position against every later point by brute force:
// sum_{j=M}^{i-1} dist(p_i, p_j) >= sum_{j=M}^{i-1} dist(p_k, p_j) for all k > i.
TEST(BillboardCloud, ProgressiveOrderPutsTheFarthestNext) {
  std::mt19937_64 rng(5);
  const std::vector<Eigen::Vector3f> ball = blue_noise_ball(rng);
  const std::size_t fixed = 8;
  const std::vector<Eigen::Vector3f> order = progressive_order(ball, fixed);
  ASSERT_EQ(order.size(), ball.size());
  for (std::size_t i = 0; i < fixed; ++i) EXPECT_EQ(order[i], ball[i]);
  // A permutation: every input point once.
  std::vector<bool> used(ball.size(), false);
  for (const auto& p : order) {
    const auto it = std::find(ball.begin(), ball.end(), p);
    ASSERT_NE(it, ball.end());
    used[static_cast<std::size_t>(it - ball.begin())] = true;
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), true), static_cast<long>(ball.size()));
  const auto summed = [&](std::size_t point, std::size_t placed) {
    double s = 0.0;
    for (std::size_t j = fixed; j < placed; ++j) s += (order[point] - order[j]).norm();
    return s;
  };
  for (std::size_t i = fixed + 1; i < order.size(); ++i) {
    const double mine = summed(i, i);
    for (std::size_t k = i + 1; k < order.size(); ++k) {
      ASSERT_GE(mine, summed(k, i) - 1e-4) << "position " << i << ", later point " << k;
    }
  }
  // The point of it: the first sixteen free points spread through the ball (their centroid
  // near the centre), where the blue-noise order fills the octree cell by cell.
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  for (std::size_t i = fixed; i < fixed + 16; ++i) centroid += order[i] / 16.0f;
  EXPECT_LT(centroid.norm(), 0.25f);
}

}  // namespace
}  // namespace fspm::crown
