// Reference images against closed forms: a cylinder rendered in parallel projection at a known
// scale covers its analytic projected area (a 2r x L rectangle from the side, a disc of radius r
// from above), counted in pixels that differ from the background.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "graphics/instanced_mesh.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

// Pixels differing from the background of their row (the gradient background varies by row
// only; column 0 is background in these scenes).
std::size_t silhouette_pixels(const Image& image) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y) {
    const auto* bg = image.pixel(0, y);
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      int diff = 0;
      for (int c = 0; c < 3; ++c) diff = std::max(diff, std::abs(p[c] - bg[c]));
      if (diff > 25) ++n;
    }
  }
  return n;
}

constexpr double kRadius = 0.1, kLength = 1.0, kViewHeight = 2.0;
constexpr int kPixels = 400;

TriangleMesh cylinder() {
  TreeGraph t;
  testing::add(t, kNoNode, {0, 0, 0}, {0, 0, kLength}, kRadius, 0, 0);
  MeshOptions o;
  o.edge_length_m = 0.005;
  o.max_sides = 64;  // 64 sides: the polygon's width is within 0.12 % of the circle's
  return mesh_tree(t, o);
}

RenderOptions ortho(View view) {
  RenderOptions o;
  o.width = o.height = kPixels;
  o.view = view;
  o.ground = false;
  o.ortho_height_m = kViewHeight;
  return o;
}

TEST(RenderReference, CylinderSideSilhouetteIsItsProjectedRectangle) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const double pixel_m = kViewHeight / kPixels;
  const double expected = 2.0 * kRadius * kLength / (pixel_m * pixel_m);  // 8000 pixels
  for (View view : {View::kFront, View::kSide}) {
    const Image image = render_mesh(cylinder(), ortho(view));
    const std::size_t n = silhouette_pixels(image);
    RecordProperty(view == View::kFront ? "front_pixels" : "side_pixels", static_cast<int>(n));
    EXPECT_NEAR(static_cast<double>(n), expected, 0.02 * expected);
  }
}

TEST(RenderReference, CylinderTopSilhouetteIsItsDisc) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const double pixel_m = kViewHeight / kPixels;
  const double expected = std::numbers::pi * kRadius * kRadius / (pixel_m * pixel_m);  // 1257
  const Image image = render_mesh(cylinder(), ortho(View::kTop));
  const std::size_t n = silhouette_pixels(image);
  RecordProperty("top_pixels", static_cast<int>(n));
  EXPECT_NEAR(static_cast<double>(n), expected, 0.03 * expected);
}

TEST(RenderReference, InstancedCopiesAddTheirAreas) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  // Three copies side by side along x (0.5 m apart, not overlapping), one at half scale: areas
  // 1 + 1 + 1/4 of one cylinder's.
  const InstancedMesh one = InstancedMesh::single(cylinder());
  std::vector<PartPlacement> placements(3);
  placements[1].translation.x() = -0.5f;
  placements[2].translation.x() = 0.5f;
  placements[2].linear *= 0.5f;
  const InstancedMesh three = place_parts({one}, placements);
  RenderOptions o = ortho(View::kFront);
  o.ortho_height_m = 2.0 * kViewHeight;  // the view is centred on the bounds, keep all in frame
  const double pixel_m = o.ortho_height_m / kPixels;
  const double expected = 2.25 * 2.0 * kRadius * kLength / (pixel_m * pixel_m);  // 4500
  const Image image = render_scene(three, o);
  const std::size_t n = silhouette_pixels(image);
  RecordProperty("instanced_pixels", static_cast<int>(n));
  EXPECT_NEAR(static_cast<double>(n), expected, 0.03 * expected);
}

}  // namespace
}  // namespace fspm::graphics
