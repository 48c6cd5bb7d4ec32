#include "graphics/translucent_sort.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fspm::graphics {
namespace {

// Brute force: the place of triangle i in a back-to-front order is the number of triangles
// strictly farther from the eye plus those as far with a smaller index. Integer coordinates keep
// every squared distance exact, so ties are real ties.
std::vector<std::uint32_t> oracle_order(const std::vector<Eigen::Vector3f>& c,
                                        const Eigen::Vector3f& eye) {
  const auto d2 = [&](std::size_t i) {
    const Eigen::Vector3d v = (c[i] - eye).cast<double>();
    return v.dot(v);
  };
  std::vector<std::uint32_t> order(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    std::size_t place = 0;
    for (std::size_t j = 0; j < c.size(); ++j) {
      if (d2(j) > d2(i) || (d2(j) == d2(i) && j < i)) ++place;
    }
    order[place] = static_cast<std::uint32_t>(i);
  }
  return order;
}

TEST(TranslucentSort, MatchesBruteForceOracleWithTies) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coordinate(-6, 6);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Eigen::Vector3f> centroids;
    for (int i = 0; i < 300; ++i) {  // 13^3 lattice points: many equal distances
      centroids.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
    }
    const Eigen::Vector3f eye(coordinate(rng), coordinate(rng), coordinate(rng) + 20);
    EXPECT_EQ(back_to_front(centroids, eye), oracle_order(centroids, eye)) << "trial " << trial;
  }
}

TEST(TranslucentSort, FarthestFirstByHand) {
  // Eye at the origin: distances 5, 1, 5 (a tie: index order), 3.
  const std::vector<Eigen::Vector3f> c = {{3, 4, 0}, {0, 1, 0}, {0, 0, -5}, {0, 3, 0}};
  EXPECT_EQ(back_to_front(c, Eigen::Vector3f::Zero()), (std::vector<std::uint32_t>{0, 2, 3, 1}));
  // From (0, 10, 0): squared distances 45, 81, 125, 49.
  EXPECT_EQ(back_to_front(c, Eigen::Vector3f(0, 10, 0)), (std::vector<std::uint32_t>{2, 1, 3, 0}));
  EXPECT_TRUE(back_to_front({}, Eigen::Vector3f::Zero()).empty());
}

TEST(TranslucentSort, CentroidsOfASoup) {
  const std::vector<Eigen::Vector3f> corners = {{0, 0, 0}, {3, 0, 0}, {0, 3, 0},
                                                {1, 1, 1}, {1, 1, 4}, {4, 1, 1}};
  const auto c = soup_centroids(corners);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_TRUE(c[0].isApprox(Eigen::Vector3f(1, 1, 0)));
  EXPECT_TRUE(c[1].isApprox(Eigen::Vector3f(2, 1, 2)));
}

}  // namespace
}  // namespace fspm::graphics
