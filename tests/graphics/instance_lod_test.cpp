// Level of detail per instance: plants in a row along the view axis against an oracle written
// here (each instance's distance against the switch distances of expression 2 and the leaf
// shares of the pruning fall-off), culling behind the camera, the jitter's determinism.
#include "graphics/instance_lod.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

constexpr std::size_t kLeaves = 40;
constexpr double kPi = 3.141592653589793;

void add_triangle(TriangleMesh& m, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                  const Eigen::Vector3f& c, Material material) {
  const auto n = static_cast<std::uint32_t>(m.positions.size());
  for (const auto& p : {a, b, c}) {
    m.positions.push_back(p);
    m.normals.push_back(Eigen::Vector3f::UnitY());
    m.uvs.push_back(Eigen::Vector2f::Zero());
  }
  m.triangles.push_back({n, n + 1, n + 2});
  m.materials.push_back(material);
}

// A plant filling the box [-0.5, 0.5]^2 x [0, 2]: `bark` bark triangles (the first spans the
// box's diagonal) and kLeaves leaves, each a quad of two triangles sharing two vertices.
TriangleMesh synthetic_plant(std::size_t bark) {
  TriangleMesh m;
  add_triangle(m, {-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 2.0f}, Material::kBark);
  for (std::size_t t = 1; t < bark; ++t) {
    const float z = 0.1f + 1.8f * static_cast<float>(t) / static_cast<float>(bark);
    add_triangle(m, {0.0f, 0.0f, z}, {0.05f, 0.0f, z}, {0.0f, 0.05f, z + 0.05f}, Material::kBark);
  }
  for (std::size_t k = 0; k < kLeaves; ++k) {
    const float z = 0.5f + 1.2f * static_cast<float>(k) / kLeaves, x = 0.3f;
    const auto n = static_cast<std::uint32_t>(m.positions.size());
    for (const Eigen::Vector3f& p :
         {Eigen::Vector3f(x, 0, z), Eigen::Vector3f(x + 0.1f, 0, z),
          Eigen::Vector3f(x + 0.1f, 0, z + 0.1f), Eigen::Vector3f(x, 0, z + 0.1f)}) {
      m.positions.push_back(p);
      m.normals.push_back(Eigen::Vector3f::UnitY());
      m.uvs.push_back(Eigen::Vector2f::Zero());
    }
    m.triangles.push_back({n, n + 1, n + 2});
    m.triangles.push_back({n, n + 2, n + 3});
    m.materials.insert(m.materials.end(), 2, Material::kLeaf);
  }
  return m;
}

// OpenGL's perspective (gluPerspective) times a look-at from `eye` along +x, z up.
Eigen::Matrix4d view_projection(const Eigen::Vector3d& eye) {
  const double fovy = 60.0 * kPi / 180.0, aspect = 1.5, near = 0.1, far = 1000.0;
  const double f = 1.0 / std::tan(fovy / 2.0);
  Eigen::Matrix4d proj = Eigen::Matrix4d::Zero();
  proj(0, 0) = f / aspect;
  proj(1, 1) = f;
  proj(2, 2) = (far + near) / (near - far);
  proj(2, 3) = 2.0 * far * near / (near - far);
  proj(3, 2) = -1.0;
  // Camera axes: right = -y, up = z, looking along -back = +x.
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  const Eigen::Vector3d right(0, -1, 0), up(0, 0, 1), back(-1, 0, 0);
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = back.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -up.dot(eye);
  view(2, 3) = -back.dot(eye);
  return proj * view;
}

struct Row {
  LodScene scene;
  std::vector<std::size_t> bark = {300, 60, 12};  // bark triangles per resolution
  std::vector<double> x;                          // placement x, plants at y = z = 0
};

// `ahead` plants at x = 2.5, 2.5 + spacing, ... and `behind` at x = -2.5, -2.5 - spacing, ...
Row row_of_plants(const LodOptions& o, std::size_t ahead, std::size_t behind,
                  double spacing_m = 5.0) {
  Row row;
  std::vector<TriangleMesh> resolutions;
  for (std::size_t b : row.bark) resolutions.push_back(synthetic_plant(b));
  row.scene.plants.push_back(make_lod_plant(resolutions, o, 7));
  for (std::size_t i = 0; i < ahead + behind; ++i) {
    const double x = i < ahead ? 2.5 + spacing_m * static_cast<double>(i)
                               : -2.5 - spacing_m * static_cast<double>(i - ahead);
    PartPlacement p;
    p.translation = Eigen::Vector3f(static_cast<float>(x), 0.0f, 0.0f);
    row.scene.placements.push_back(p);
    row.x.push_back(x);
  }
  return row;
}

// The oracle: resolution from the distance alone (every plant as large as the largest, so
// expression 2 is 3 (1 - d / D_max): resolution 0 up to D_max / 3, 1 up to 2 D_max / 3, then 2).
std::size_t oracle_resolution(double d, const LodOptions& o) {
  if (d <= o.max_distance_m / 3.0) return 0;
  if (d <= 2.0 * o.max_distance_m / 3.0) return 1;
  return 2;
}

// Leaf triangles drawn: 2 per leaf, ceil(share N) leaves, share the smallest listed one at or
// above (d_ref / d)^2.
std::size_t oracle_leaf_triangles(double d, const LodOptions& o) {
  const double wanted = d <= o.prune_distance_m ? 1.0 : std::pow(o.prune_distance_m / d, 2.0);
  double share = 1.0;
  for (double f : o.leaf_fractions) {
    if (f >= wanted) share = f;
  }
  return 2 * static_cast<std::size_t>(std::ceil(share * kLeaves - 1e-9));
}

TEST(InstanceLod, TrianglesPerLevelMatchTheDistanceOracle) {
  LodOptions o;
  o.max_distance_m = 60.0;
  o.prune_distance_m = 15.0;
  o.jitter = 0.0;
  Row row = row_of_plants(o, 30, 0);
  const Eigen::Vector3d eye(0.0, 0.0, 1.0);  // the height of the plants' sphere centres
  const auto choice = select_lod(row.scene, eye, view_projection(eye), o);
  ASSERT_EQ(choice.size(), row.x.size());
  std::map<std::size_t, std::size_t> expected, drawn;  // triangles per resolution
  for (std::size_t i = 0; i < row.x.size(); ++i) {
    const double d = row.x[i];  // along the axis through the sphere centres
    ASSERT_TRUE(choice[i].visible) << i;
    EXPECT_NEAR(choice[i].distance_m, d, 1e-5);
    EXPECT_EQ(choice[i].resolution, oracle_resolution(d, o)) << "x = " << d;
    expected[oracle_resolution(d, o)] +=
        row.bark[oracle_resolution(d, o)] + oracle_leaf_triangles(d, o);
  }
  const std::vector<MeshInstance> instances = lod_instances(row.scene, choice);
  const std::size_t shares = o.leaf_fractions.size();
  for (const MeshInstance& inst : instances) {
    drawn[inst.mesh / shares] += row.scene.meshes()[inst.mesh]->triangle_count();
  }
  EXPECT_EQ(drawn, expected);
  ASSERT_EQ(expected.size(), 3u);  // every level used: the check can fail for each
  std::size_t total = 0;
  for (const auto& [level, n] : expected) total += n;
  EXPECT_EQ(lod_triangle_count(row.scene, instances), total);
}

TEST(InstanceLod, PlantsBehindTheCameraAreCulled) {
  LodOptions o;
  o.jitter = 0.0;
  Row row = row_of_plants(o, 10, 10);
  const Eigen::Vector3d eye(0.0, 0.0, 1.0);
  const auto choice = select_lod(row.scene, eye, view_projection(eye), o);
  std::size_t culled = 0;
  for (std::size_t i = 0; i < row.x.size(); ++i) {
    // Sphere radius sqrt(1.5) < 2.5: every plant behind lies wholly behind the near plane.
    EXPECT_EQ(choice[i].visible, row.x[i] > 0.0) << "x = " << row.x[i];
    culled += choice[i].visible ? 0 : 1;
  }
  EXPECT_EQ(culled, 10u);
  EXPECT_EQ(lod_instances(row.scene, choice).size(), 10u);
  // Turning round (eye at the far end looking along +x still) culls the whole row.
  const Eigen::Vector3d beyond(100.0, 0.0, 1.0);
  for (const InstanceLod& c : select_lod(row.scene, beyond, view_projection(beyond), o)) {
    EXPECT_FALSE(c.visible);
  }
}

TEST(InstanceLod, JitterStaysWithinItsBandAndIsDeterministic) {
  LodOptions o;
  o.max_distance_m = 60.0;
  o.jitter = 0.5;
  Row row = row_of_plants(o, 120, 0, 1.0);  // a plant every metre: many near each switch
  const Eigen::Vector3d eye(0.0, 0.0, 1.0);
  const auto a = select_lod(row.scene, eye, view_projection(eye), o);
  const auto b = select_lod(row.scene, eye, view_projection(eye), o);
  std::size_t differs = 0;
  for (std::size_t i = 0; i < row.x.size(); ++i) {
    EXPECT_EQ(a[i].resolution, b[i].resolution);
    EXPECT_EQ(a[i].share, b[i].share);
    const double d = row.x[i];
    // Within the resolutions of d scaled by 1 -/+ jitter / 2.
    EXPECT_GE(a[i].resolution, oracle_resolution(d * 0.75, o));
    EXPECT_LE(a[i].resolution, oracle_resolution(d * 1.25, o));
    differs += a[i].resolution != oracle_resolution(d, o) ? 1 : 0;
  }
  EXPECT_GT(differs, 0u);  // switch distances do vary from plant to plant
  double mean = 0.0;
  for (std::size_t i = 0; i < 4000; ++i) {
    const double h = lod_jitter(i);
    ASSERT_GE(h, -0.5);
    ASSERT_LT(h, 0.5);
    mean += h / 4000.0;
  }
  EXPECT_NEAR(mean, 0.0, 0.03);
}

// Impostors: a plant as large as the largest switches at the impostor distance, one half as
// large at half of it (the same projected size); impostors leave the mesh instances.
TEST(InstanceLod, ImpostorsFromTheDistanceOfEqualProjectedSize) {
  LodOptions o;
  o.jitter = 0.0;
  o.max_distance_m = 200.0;
  o.impostor_distance_m = 30.0;
  Row row = row_of_plants(o, 24, 0, 2.0);
  for (std::size_t i = 1; i < row.x.size(); i += 2) {
    row.scene.placements[i].linear = 0.5f * Eigen::Matrix3f::Identity();  // half as large
  }
  const Eigen::Vector3d eye(0.0, 0.0, 0.0);
  const auto choice = select_lod(row.scene, eye, view_projection(eye), o);
  const double r = row.scene.plants[0].sphere.radius;
  std::size_t impostors = 0;
  for (std::size_t i = 0; i < row.x.size(); ++i) {
    const auto& p = row.scene.placements[i];
    const double scale = p.linear(0, 0);
    // The placed centre of the box's sphere: (x, 0, scale z_c).
    const Eigen::Vector3d c(row.x[i], 0.0, scale * row.scene.plants[0].sphere.center.z());
    EXPECT_NEAR(choice[i].distance_m, c.norm(), 1e-6);
    EXPECT_EQ(choice[i].impostor, c.norm() > 30.0 * scale) << "x = " << row.x[i];
    impostors += choice[i].impostor ? 1 : 0;
  }
  EXPECT_GT(impostors, 0u);
  EXPECT_LT(impostors, row.x.size());
  EXPECT_EQ(lod_instances(row.scene, choice).size(), row.x.size() - impostors);
  EXPECT_GT(r, 0.0);
  o.impostor_distance_m = 0.0;  // none
  for (const InstanceLod& c : select_lod(row.scene, eye, view_projection(eye), o)) {
    EXPECT_FALSE(c.impostor);
  }
}

TEST(InstanceLod, RejectsBadOptions) {
  LodOptions o;
  o.leaf_fractions = {0.5, 0.25};
  EXPECT_THROW(o.validate(), ValueError);
  o.leaf_fractions = {1.0, 1.0};
  EXPECT_THROW(o.validate(), ValueError);
  o = LodOptions{};
  o.jitter = 1.0;
  EXPECT_THROW(o.validate(), ValueError);
  o = LodOptions{};
  o.impostor_distance_m = -1.0;
  EXPECT_THROW(o.validate(), ValueError);
  EXPECT_THROW(make_lod_plant({}, LodOptions{}, 1), ValueError);
}

}  // namespace
}  // namespace fspm::graphics
