// Relief-mapped crowns (Argudo 5.1): the radius lookup against the cubemap layout written out
// here from its description (crown/cubemap.hpp, docs/crown.md), and the viewer's ray-cast crown
// against the same surface drawn as triangles.
#include "graphics/relief_crown.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "fspm/error.hpp"
#include "graphics/image.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

// Face f, texel centre (x, y) of an N x N face: front -y, right +x, back +y, left -x (seen from
// outside, z up, so the four form one strip), top +z with the front face below it, bottom -z
// with the front face above it.
Eigen::Vector3f texel_direction(int face, int x, int y, int n) {
  const float u = 2.0f * (x + 0.5f) / n - 1.0f, v = 2.0f * (y + 0.5f) / n - 1.0f;
  const Eigen::Vector3f d[6] = {{u, -1, -v},  {1, u, -v}, {-u, 1, -v},
                                {-1, -u, -v}, {u, -v, 1}, {u, v, -1}};
  return d[face].normalized();
}

// A lopsided crown: R(d) = 1 + 0.3 dx + 0.2 dy - 0.25 dz, so a face read the wrong way round
// gives the wrong radius.
float lopsided_radius(const Eigen::Vector3f& d) {
  return 1.0f + 0.3f * d.x() + 0.2f * d.y() - 0.25f * d.z();
}

ReliefCrown crown_of(int n, float (*radius)(const Eigen::Vector3f&)) {
  ReliefCrown c;
  c.face_size = n;
  c.radius_m.resize(6 * n * n);
  c.rgb.assign(3 * 6 * n * n, 0);
  for (int f = 0; f < 6; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * 6 * n + f * n + x;
        c.radius_m[i] = radius(texel_direction(f, x, y, n));
        c.rgb[3 * i] = 205;  // red: 0.8, 0.1, 0.1
        c.rgb[3 * i + 1] = c.rgb[3 * i + 2] = 26;
      }
    }
  }
  c.centre_m = {0.0f, 0.0f, 1.5f};
  return c;
}

TEST(ReliefCrown, RadiusLookupFollowsTheCubemapLayout) {
  const ReliefCrown c = crown_of(64, lopsided_radius);
  std::mt19937_64 rng(3);
  std::normal_distribution<float> g;
  for (int k = 0; k < 2000; ++k) {
    const Eigen::Vector3f d = Eigen::Vector3f(g(rng), g(rng), g(rng)).normalized();
    EXPECT_NEAR(relief_radius_m(c, d), lopsided_radius(d), 0.01f) << d.transpose();
  }
  EXPECT_NEAR(c.max_radius_m(), 1.0f + std::sqrt(0.09f + 0.04f + 0.0625f), 0.01f);
}

TEST(ReliefCrown, RefusesWhatCannotBeDrawn) {
  EXPECT_NO_THROW(crown_of(4, lopsided_radius).validate());
  ReliefCrown c = crown_of(4, lopsided_radius);
  c.radius_m.pop_back();
  EXPECT_THROW(c.validate(), ValueError);
  c = crown_of(4, lopsided_radius);
  c.radius_m[5] = std::nanf("");
  EXPECT_THROW(c.validate(), ValueError);
  c = crown_of(4, lopsided_radius);
  c.placements.front()(0, 0) = 0.0f;
  c.placements.front()(1, 1) = 0.0f;
  EXPECT_THROW(c.validate(), ValueError);
}

// The lopsided surface as triangles: a latitude-longitude sphere around the centre with each
// vertex at R(d) d, coloured like the crown.
TriangleMesh lopsided_mesh(const Eigen::Vector3f& centre) {
  TriangleMesh m;
  const int slices = 96, stacks = 48;
  for (int i = 0; i <= stacks; ++i) {
    for (int j = 0; j <= slices; ++j) {
      const float th = static_cast<float>(M_PI) * i / stacks;
      const float ph = 2.0f * static_cast<float>(M_PI) * j / slices;
      const Eigen::Vector3f d(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                              std::cos(th));
      m.positions.push_back(centre + lopsided_radius(d) * d);
      m.normals.push_back(d);
      m.uvs.emplace_back(0.0f, 0.0f);
    }
  }
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const auto a = static_cast<std::uint32_t>(i * (slices + 1) + j), b = a + slices + 1;
      m.triangles.push_back({a, a + 1, b});
      m.triangles.push_back({a + 1, b + 1, b});
      m.materials.insert(m.materials.end(), 2, Material::kLeaf);
    }
  }
  for (const auto& [name, value] : {std::pair{"red", 0.8f}, {"green", 0.1f}, {"blue", 0.1f}}) {
    m.add_attribute(name).assign(m.positions.size(), value);
  }
  return m;
}

std::vector<bool> red_pixels(const Image& image) {
  std::vector<bool> red;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      red.push_back(p[0] > p[1] + 25 && p[0] > p[2] + 25);  // lit or in shade
    }
  }
  return red;
}

// The lopsided crown beside a small trunk, seen from the viewer's starting camera: drawn as
// triangles, or ray cast from its cubemaps; both framed alike (degenerate triangles at the
// corners of the cube the viewer frames a relief crown by).
class ReliefView : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!viewer_available()) GTEST_SKIP() << "built without the viewer";
    if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
    TreeGraph tree;
    testing::add(tree, kNoNode, {0, 0, 0}, {0, 0, 0.6}, 0.05, 0, 0);
    trunk_ = mesh_tree(tree, {});
    crown_ = crown_of(128, lopsided_radius);
    const float r = crown_.max_radius_m();
    for (int k = 0; k < 8; ++k) {
      const auto v = static_cast<std::uint32_t>(trunk_.positions.size());
      trunk_.positions.push_back(
          crown_.centre_m + r * Eigen::Vector3f(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
      trunk_.normals.push_back(Eigen::Vector3f::UnitZ());
      trunk_.uvs.emplace_back(0.0f, 0.0f);
      for (auto& a : trunk_.attributes) a.values.push_back(0.0f);
      trunk_.triangles.push_back({v, v, v});
      trunk_.materials.push_back(Material::kBark);
    }
    dir_ = std::filesystem::temp_directory_path() / ("fspm_relief_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  Image shot(bool relief, bool shadows, int width = 240, int height = 180) {
    ViewerOptions o;
    o.width = width;
    o.height = height;
    o.shadows = shadows;
    o.screenshot = (dir_ / "shot.png").string();
    TriangleMesh mesh = trunk_;
    if (relief) {
      o.relief_crowns = {crown_};
    } else {
      mesh.append(lopsided_mesh(crown_.centre_m));
    }
    run_viewer({mesh}, {0.0}, o);
    return read_image(o.screenshot);
  }

  TriangleMesh trunk_;
  ReliefCrown crown_;
  std::filesystem::path dir_;
};

double intersection_over_union(const std::vector<bool>& a, const std::vector<bool>& b,
                               std::size_t& either) {
  std::size_t both = 0;
  either = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    both += a[i] && b[i];
    either += a[i] || b[i];
  }
  return either == 0 ? 0.0 : static_cast<double>(both) / static_cast<double>(either);
}

// The ray-cast crown covers the pixels the triangulated surface covers.
TEST_F(ReliefView, DrawsTheSurfaceOfItsRadiusCubemap) {
  std::size_t either = 0;
  const double iou = intersection_over_union(red_pixels(shot(false, false)),
                                             red_pixels(shot(true, false)), either);
  ASSERT_GT(either, 2000u);  // the crown fills a good part of the picture
  EXPECT_GT(iou, 0.97);
}

// Pixels outside the crown that the shadows darken: the ground under the crown.
std::vector<bool> shadowed_pixels(const Image& lit, const Image& unlit) {
  const std::vector<bool> crown = red_pixels(lit);
  std::vector<bool> shadow;
  for (int y = 0; y < lit.height; ++y) {
    for (int x = 0; x < lit.width; ++x) {
      const auto *a = lit.pixel(x, y), *b = unlit.pixel(x, y);
      const int darker = (b[0] - a[0]) + (b[1] - a[1]) + (b[2] - a[2]);
      shadow.push_back(!crown[shadow.size()] && darker > 30);
    }
  }
  return shadow;
}

// The ray-cast crown casts the triangulated crown's shadow: the same march from the sun writes
// its depth moments into the variance shadow map.
TEST_F(ReliefView, CastsTheShadowOfItsSurface) {
  const std::vector<bool> mesh = shadowed_pixels(shot(false, true), shot(false, false));
  const std::vector<bool> relief = shadowed_pixels(shot(true, true), shot(true, false));
  std::size_t either = 0;
  const double iou = intersection_over_union(mesh, relief, either);
  ASSERT_GT(either, 300u);
  EXPECT_GT(iou, 0.8) << either << " pixels in either shadow";
  std::printf("shadow IoU %.3f of %zu\n", iou, either);
}

// The offscreen VTK render ray casts the crown into its picture (relief_composite.hpp): the same
// pixels as the crown's triangles, in the same frame, hidden behind nearer geometry.
TEST_F(ReliefView, OffscreenRendersRayCastTheCrown) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  RenderOptions o;
  o.width = 320;
  o.height = 240;
  const float r = crown_.max_radius_m();
  o.frame = Eigen::AlignedBox3f(crown_.centre_m.array() - r, crown_.centre_m.array() + r);
  o.frame->extend(Eigen::Vector3f::Zero());
  TriangleMesh with_crown = trunk_;
  with_crown.append(lopsided_mesh(crown_.centre_m));
  // Every view, so that a crown turned or mirrored in the ray cast would show.
  for (const View view : {View::kFront, View::kSide, View::kTop, View::kIso}) {
    o.view = view;
    o.relief_crowns.clear();
    // Crown pixels: those that differ from the picture without the crown (the two forms are lit
    // differently, so their colours are not compared).
    const Image bare = render_mesh(trunk_, o);
    const auto covered = [&](const Image& image) {
      std::vector<bool> out;
      for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        int d = 0;
        for (int k = 0; k < 3; ++k) d += std::abs(image.rgba[i + k] - bare.rgba[i + k]);
        out.push_back(d > 30);
      }
      return out;
    };
    const std::vector<bool> mesh = covered(render_mesh(with_crown, o));
    o.relief_crowns = {crown_};
    const std::vector<bool> relief = covered(render_mesh(trunk_, o));
    std::size_t either = 0;
    const double iou = intersection_over_union(mesh, relief, either);
    ASSERT_GT(either, 3000u);
    EXPECT_GT(iou, 0.97) << either << " pixels in either, view " << view_name(view);
    std::printf("offscreen IoU %.3f of %zu\n", iou, either);
  }
  // A wall in front of the crown hides it.
  o.view = View::kFront;
  TriangleMesh wall = trunk_;
  const auto v = static_cast<std::uint32_t>(wall.positions.size());
  const Eigen::Vector3f c = crown_.centre_m;
  for (const auto& [x, z] : {std::pair{-3.0f, -1.0f}, {3.0f, -1.0f}, {3.0f, 4.0f}, {-3.0f, 4.0f}}) {
    wall.positions.push_back(c + Eigen::Vector3f(x, -2.0f * r, z));
    wall.normals.push_back(-Eigen::Vector3f::UnitY());
    wall.uvs.emplace_back(0.0f, 0.0f);
    for (auto& a : wall.attributes) a.values.push_back(0.0f);
  }
  wall.triangles.push_back({v, v + 1, v + 2});
  wall.triangles.push_back({v, v + 2, v + 3});
  wall.materials.insert(wall.materials.end(), 2, Material::kObstacle);
  const std::vector<bool> hidden = red_pixels(render_mesh(wall, o));
  EXPECT_EQ(std::count(hidden.begin(), hidden.end(), true), 0);
}

// Billboard centres for the lopsided crown: jittered points of a grid through its bounding cube,
// kept inside the crown.
std::vector<Eigen::Vector3f> lopsided_billboards(const ReliefCrown& crown) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> jitter(-0.07f, 0.07f);
  std::vector<Eigen::Vector3f> out;
  const float r = crown.max_radius_m();
  for (int i = -6; i <= 6; ++i) {
    for (int j = -6; j <= 6; ++j) {
      for (int k = -6; k <= 6; ++k) {
        const Eigen::Vector3f q =
            r *
            Eigen::Vector3f(i / 6.0f + jitter(rng), j / 6.0f + jitter(rng), k / 6.0f + jitter(rng));
        if (q.norm() > 0.0f && q.norm() < lopsided_radius(q.normalized())) {
          out.push_back(crown.centre_m + q);
        }
      }
    }
  }
  return out;
}

// The viewer's starting camera at 1024 x 768 sees the crown about 190 pixels in radius: the
// detailed crown of Argudo 5.2. Every leaf it draws lies inside the crown (cropped by the radius
// cubemap, so inside the ray-cast silhouette), the leaves fill most of that silhouette, and they
// show as leaves: the picture differs from the relief's.
TEST_F(ReliefView, BillboardsNearTheCameraAreLeavesCroppedToTheCrown) {
  const std::vector<bool> relief = red_pixels(shot(true, false, 1024, 768));
  crown_.billboards_m = lopsided_billboards(crown_);
  ASSERT_GT(crown_.billboards_m.size(), 200u);
  const std::vector<bool> leaves = red_pixels(shot(true, false, 1024, 768));
  std::size_t in_relief = 0, leaf = 0, outside = 0;
  for (std::size_t i = 0; i < relief.size(); ++i) {
    in_relief += relief[i];
    leaf += leaves[i];
    // A leaf pixel outside the relief's silhouette, not even beside its edge.
    const std::size_t x = i % 1024, y = i / 1024;
    if (leaves[i] && !relief[i] && x > 0 && x + 1 < 1024 && y > 0 && y + 1 < 768 &&
        !relief[i - 1] && !relief[i + 1] && !relief[i - 1024] && !relief[i + 1024]) {
      ++outside;
    }
  }
  ASSERT_GT(in_relief, 30000u);
  EXPECT_LT(static_cast<double>(outside), 0.002 * static_cast<double>(leaf));
  EXPECT_GT(static_cast<double>(leaf), 0.5 * static_cast<double>(in_relief));
  EXPECT_LT(static_cast<double>(leaf),
            0.99 * static_cast<double>(in_relief));  // gaps between leaves
  std::printf("leaves cover %.3f of the crown, %zu of %zu outside\n",
              static_cast<double>(leaf) / static_cast<double>(in_relief), outside, leaf);
}

// Small on the screen (240 x 180: about 45 pixels in radius), the same crown is ray cast, whether
// or not it has billboards.
TEST_F(ReliefView, DistantCrownsAreRayCastEvenWithBillboards) {
  const Image plain = shot(true, true);
  crown_.billboards_m = lopsided_billboards(crown_);
  const Image with_billboards = shot(true, true);
  ASSERT_EQ(plain.rgba.size(), with_billboards.rgba.size());
  EXPECT_TRUE(plain.rgba == with_billboards.rgba);
}

// The CPU march against the closed form for a sphere: a crown of radius 1 everywhere is entered
// at t = -b - sqrt(b^2 - |o - c|^2 + 1).
TEST(ReliefCrown, CpuMarchMeetsTheSphereWhereTheClosedFormDoes) {
  const ReliefCrown c = crown_of(16, [](const Eigen::Vector3f&) { return 1.0f; });
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int hits = 0;
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3f origin = c.centre_m + Eigen::Vector3f(3.0f, u(rng), u(rng));
    const Eigen::Vector3f target = c.centre_m + 0.8f * Eigen::Vector3f(u(rng), u(rng), u(rng));
    const Eigen::Vector3f dir = (target - origin).normalized();
    const Eigen::Vector3f oc = origin - c.centre_m;
    const float b = oc.dot(dir), disc = b * b - oc.squaredNorm() + 1.0f;
    float t = 0.0f;
    ASSERT_EQ(relief_ray_hit(c, 1.01f * c.max_radius_m(), origin, dir, t), disc > 0.0f);
    if (disc <= 0.0f) continue;
    EXPECT_NEAR(t, -b - std::sqrt(disc), 1e-4f);
    ++hits;
  }
  EXPECT_GT(hits, 150);
  float t = 0.0f;
  EXPECT_FALSE(relief_ray_hit(c, 1.01f, c.centre_m + Eigen::Vector3f(3, 0, 0), {0, 0, 1}, t));
}

TEST(ReliefCrown, BillboardCountGrowsWithTheCrownOnTheScreen) {
  EXPECT_EQ(billboard_count(kBillboardFromPx - 1.0f, 300), 0.0f);  // ray cast
  const float least = kBillboardFromPx / kAllBillboardsPx;
  EXPECT_NEAR(billboard_count(kBillboardFromPx, 300), 300.0f * least * least, 1e-3f);
  EXPECT_EQ(billboard_count(kBillboardFromPx, 50), kFewestBillboards);  // never fewer
  EXPECT_EQ(billboard_count(kAllBillboardsPx, 300), 300.0f);
  EXPECT_EQ(billboard_count(10.0f * kAllBillboardsPx, 300), 300.0f);
  // In between, the share of the crown's area on the screen.
  const float r = 0.8f * kAllBillboardsPx;
  EXPECT_NEAR(billboard_count(r, 300), 300.0f * 0.64f, 1e-3f);
  EXPECT_EQ(billboard_count(kAllBillboardsPx, 0), 0.0f);
}

}  // namespace
}  // namespace fspm::graphics
