// A crown reconstructed from a picture of one of fspm's own trees, checked against the true tree
// seen at 90 degrees. The pictures (examples/crown) are parallel projections spanning 8 m of
// height of the tree grown by `fspm grow --preset A --years 20`, rendered with
// `fspm render --leaves --view front|side --size 256x256 --ortho-height 8` (docs/crown.md).
#include <gtest/gtest.h>

#include <iostream>
#include <random>
#include <string>

#include "crown/auto_mask.hpp"
#include "crown/crown_from_photo.hpp"
#include "crown/image_io.hpp"
#include "crown/side_view.hpp"

namespace fspm::crown {
namespace {

constexpr double kImageHeightM = 8.0;

std::string example(const std::string& name) {
  return std::string(FSPM_SOURCE_DIR) + "/examples/crown/" + name;
}

int lowest_row(const Mask& m) {
  for (int y = m.height - 1; y >= 0; --y) {
    for (int x = 0; x < m.width; ++x) {
      if (m.at(x, y)) return y;
    }
  }
  return 0;
}

// Visual hull of the front and side silhouettes (both parallel projections at the same scale):
// per image row, the crown occupies at most front width x side width.
double visual_hull_m3(const Mask& front, const Mask& side, double metres_per_pixel) {
  double cells = 0.0;
  for (int y = 0; y < front.height; ++y) {
    double f = 0.0, s = 0.0;
    for (int x = 0; x < front.width; ++x) f += front.at(x, y), s += side.at(x, y);
    cells += f * s;
  }
  return cells * metres_per_pixel * metres_per_pixel * metres_per_pixel;
}

TEST(RenderedTree, SideViewOfTheReconstructionMatchesTheTree) {
  const Raster front = read_rgb(example("tree_front.png"));
  const Raster side = read_rgb(example("tree_side.png"));
  const Mask front_mask = auto_mask(front, {});
  const Mask side_mask = auto_mask(side, {});
  const double metres_per_pixel = kImageHeightM / front.height;
  // The guess that the tree looks the same from the side as from the front, for comparison.
  const double front_as_side = intersection_over_union(side_mask, front_mask);
  std::cout << "front silhouette as the side one: IoU " << front_as_side << "\n";
  for (double depth_ratio : {1.0, 0.75}) {
    CrownOptions options;
    int top = 0;
    for (bool found = false; !found; found = found || ++top >= front_mask.height) {
      for (int x = 0; x < front_mask.width && !found; ++x) found = front_mask.at(x, top);
    }
    options.height_m = metres_per_pixel * (lowest_row(front_mask) - top + 1);
    options.depth_ratio = depth_ratio;
    std::mt19937_64 rng(1);
    const CrownModel model = reconstruct_crown(front, front_mask, options, rng);
    const Mask seen = side_silhouette(model.mesh, front.width, front.height, metres_per_pixel,
                                      lowest_row(front_mask));
    const double iou = intersection_over_union(side_mask, seen);
    const double hull = visual_hull_m3(front_mask, side_mask, metres_per_pixel);
    std::cout << "depth ratio " << depth_ratio << ": side IoU " << iou << ", volume "
              << model.volume_m3 << " m3, visual hull " << hull << " m3\n";
    // Measured 0.56 (depth ratio 1) and 0.71 (0.75, this tree's own depth over width).
    EXPECT_GT(iou, depth_ratio == 1.0 ? 0.5 : 0.65);
    EXPECT_LT(model.volume_m3, 1.2 * hull);
    EXPECT_GT(model.volume_m3, 0.3 * hull);
  }
}

}  // namespace
}  // namespace fspm::crown
