#include "graphics/instanced_mesh.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>

#include "fspm/error.hpp"
#include "graphics/image.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/render.hpp"
#include "graphics/scene_file.hpp"
#include "graphics/viewer.hpp"
#include "tests/graphics/mesh_checks.hpp"
#include "tests/graphics/test_trees.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;
using testing::add;

Eigen::Matrix3d rot(double deg, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(deg * 3.141592653589793 / 180.0, axis).toRotationMatrix();
}

// Three substructures: a trunk of three internodes with a leaf, bearing two copies of a lateral
// (two internodes and a leaf), which bears one copy of a twig. Five occurrences in all.
InstancedTree three_level_plant() {
  InstancedTree plant;
  plant.prototypes.resize(3);
  TreeGraph& trunk = plant.prototypes[0].geometry;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const NodeId n0 = add(trunk, kNoNode, {0, 0, 0}, {0, 0, 1}, 0.05, 0, 0);
  const NodeId n1 = add(trunk, n0, {0, 0, 1}, {0, 0, 2}, 0.05, 1, 0);
  add(trunk, n1, {0, 0, 2}, {0, 0, 3}, 0.05, 2, 0);
  add(trunk, n1, {0, 0, 2}, {0.2, 0, 2}, 0.0, 1.5, 1, OrganKind::kLeaf);
  plant.prototypes[0].children = {
      {1, n0, rot(45, Eigen::Vector3d::UnitY()), {0, 0, 1}},
      {1, n1, rot(180, z) * rot(45, Eigen::Vector3d::UnitY()), {0, 0, 2}}};
  TreeGraph& lateral = plant.prototypes[1].geometry;
  const NodeId m0 = add(lateral, kNoNode, {0, 0, 0}, {0, 0, 0.6}, 0.02, 3, 0);
  const NodeId m1 = add(lateral, m0, {0, 0, 0.6}, {0, 0, 1.2}, 0.02, 4, 0);
  add(lateral, m1, {0, 0, 1.2}, {0, 0.15, 1.3}, 0.0, 4.5, 1, OrganKind::kLeaf);
  plant.prototypes[1].children = {{2, m0, rot(60, Eigen::Vector3d::UnitX()), {0, 0, 0.6}}};
  add(plant.prototypes[2].geometry, kNoNode, {0, 0, 0}, {0, 0, 0.4}, 0.01, 5, 0);
  return plant;
}

// Independent oracle: the explicit tree the plant stands for, built by composing the
// transforms down the substructure tree (orders offset by one per level).
void expand_into(const InstancedTree& plant, std::uint32_t p, NodeId parent,
                 const Eigen::Matrix3d& r, const Eigen::Vector3d& t, int order, TreeGraph& out) {
  const TreeGraph& g = plant.prototypes[p].geometry;
  std::vector<NodeId> map(g.size());
  for (NodeId n = 0; n < g.size(); ++n) {
    NodeData d = g.data(n);
    d.start = r * d.start + t;
    d.end = r * d.end + t;
    d.direction = r * d.direction;
    d.order = static_cast<std::uint16_t>(d.order + order);
    map[n] = out.add_node(n == 0 ? parent : map[g.parent(n)], d);
  }
  for (const auto& c : plant.prototypes[p].children) {
    expand_into(plant, c.prototype, map[c.attach], r * c.rotation, r * c.translation + t, order + 1,
                out);
  }
}

TreeGraph expand(const InstancedTree& plant) {
  TreeGraph out;
  expand_into(plant, 0, kNoNode, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), 0, out);
  return out;
}

std::vector<float> sorted(std::span<const float> v) {
  std::vector<float> s(v.begin(), v.end());
  std::sort(s.begin(), s.end());
  return s;
}

TEST(InstancedMesh, SameCountsAndBoundsAsTheExplicitTree) {
  const InstancedTree plant = three_level_plant();
  const TreeGraph explicit_tree = expand(plant);
  ASSERT_EQ(explicit_tree.size(), 4u + 2 * (3 + 1));
  MeshOptions o;
  const InstancedMesh inst = mesh_instanced(plant, o);
  const TriangleMesh reference = mesh_tree(explicit_tree, o);
  EXPECT_EQ(inst.meshes.size(), 3u);
  EXPECT_EQ(inst.instances.size(), 5u);
  EXPECT_EQ(inst.triangle_count(), reference.triangle_count());
  EXPECT_EQ(inst.vertex_count(), reference.vertex_count());
  // Each substructure stored once: fewer stored than represented triangles.
  EXPECT_LT(inst.stored_triangle_count(), inst.triangle_count());
  Eigen::Vector3f lo, hi;
  inst.bounds(lo, hi);
  // Rings may be turned about their axis (frames start afresh in each substructure): bounds
  // agree within the thickest radius.
  EXPECT_LT((lo - reference.bbox_min()).cwiseAbs().maxCoeff(), 0.05f);
  EXPECT_LT((hi - reference.bbox_max()).cwiseAbs().maxCoeff(), 0.05f);
  EXPECT_GT((hi - lo).maxCoeff(), 2.5f);

  const TriangleMesh flat = inst.flatten();
  EXPECT_EQ(flat.triangle_count(), reference.triangle_count());
  testing::expect_valid_mesh(flat);
  // Per-vertex attributes are those of the same nodes: equal as multisets.
  for (const char* name : {kAttributeOrder, kAttributeAge, kAttributeBirthTime}) {
    EXPECT_EQ(sorted(flat.attribute(name)), sorted(reference.attribute(name))) << name;
  }
}

TEST(InstancedMesh, LeavesAndGrowthFilterKeepTheExplicitCounts) {
  const InstancedTree plant = three_level_plant();
  const TreeGraph explicit_tree = expand(plant);
  MeshOptions o;
  o.leaves = true;
  for (double t : {0.5, 1.7, 3.5, 4.6, 1e9}) {
    o.max_birth_time = t;
    const InstancedMesh inst = mesh_instanced(plant, o);
    const TriangleMesh reference = mesh_tree(explicit_tree, o);
    EXPECT_EQ(inst.triangle_count(), reference.triangle_count()) << t;
    EXPECT_EQ(inst.flatten().triangle_count(Material::kLeaf),
              reference.triangle_count(Material::kLeaf))
        << t;
  }
}

TEST(InstancedMesh, BadReferencesAreValueErrors) {
  InstancedTree plant = three_level_plant();
  plant.prototypes[1].children[0].prototype = 7;
  EXPECT_THROW(mesh_instanced(plant), ValueError);
  plant = three_level_plant();
  plant.prototypes[0].children[0].attach = 99;
  EXPECT_THROW(mesh_instanced(plant), ValueError);
  EXPECT_TRUE(mesh_instanced(InstancedTree{}).instances.empty());
}

TEST(InstancedMesh, PlacingPartsComposesTransforms) {
  const InstancedMesh tree = InstancedMesh::single(mesh_tree(testing::small_tree(), {}));
  Eigen::Vector3f lo0, hi0;
  tree.bounds(lo0, hi0);
  std::vector<PartPlacement> placements;
  for (int i = 0; i < 7; ++i) {
    PartPlacement p;
    p.translation = Eigen::Vector3f(10.0f * i, 0, 0);
    placements.push_back(p);
  }
  // One more, turned a quarter about z and doubled: x extent becomes y extent.
  PartPlacement turned;
  turned.linear = 2.0f * rot(90, Eigen::Vector3d::UnitZ()).cast<float>();
  turned.translation = Eigen::Vector3f(0, 100, 0);
  placements.push_back(turned);
  const InstancedMesh scene = place_parts({tree}, placements);
  EXPECT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.instances.size(), 8u);
  EXPECT_EQ(scene.triangle_count(), 8 * tree.triangle_count());
  Eigen::Vector3f lo, hi;
  scene.bounds(lo, hi);
  EXPECT_NEAR(hi.x(), hi0.x() + 60.0f, 1e-4);
  EXPECT_NEAR(hi.y(), 100.0f + 2.0f * hi0.x(), 1e-3);  // x -> y under the quarter turn
  EXPECT_NEAR(hi.z(), std::max(hi0.z(), 2.0f * hi0.z()), 1e-3);
  const TriangleMesh flat = scene.flatten();
  testing::expect_valid_mesh(flat);
  EXPECT_THROW(place_parts({tree}, {PartPlacement{3}}), ValueError);
}

// One triangle with a normal, a texture coordinate and the attributes given, all per vertex.
TriangleMesh one_triangle(bool with_normals, const std::vector<std::string>& attributes) {
  TriangleMesh m;
  m.positions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (with_normals) m.normals = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  m.uvs = {{0, 0}, {1, 0}, {0, 1}};
  m.triangles = {{0, 1, 2}};
  m.materials = {Material::kLeaf};
  for (const auto& name : attributes) m.attributes.push_back({name, {1.0f, 2.0f, 3.0f}});
  return m;
}

// Flattening by hand: a quarter turn about z doubled moves (1, 0, 0) to (0, 2, 0) and turns the
// normal (1, 0, 0) to (0, 1, 0); indices shift by the vertices before; a column missing in a
// mesh is 0 there; order gains the instance's offset; normals only when every mesh has them.
TEST(InstancedMesh, FlattenTransformsEveryColumnAsWorkedByHand) {
  InstancedMesh scene;
  scene.meshes.push_back(one_triangle(true, {"age", kAttributeOrder}));
  scene.meshes.push_back(one_triangle(true, {"light"}));
  MeshInstance a;
  MeshInstance b;
  b.mesh = 1;
  b.linear = 2.0f * Eigen::AngleAxisf(0.5f * static_cast<float>(M_PI), Eigen::Vector3f::UnitZ())
                        .toRotationMatrix();
  b.translation = {0, 0, 5};
  MeshInstance c = a;
  c.order_offset = 4;
  scene.instances = {a, b, c};
  const TriangleMesh flat = scene.flatten();
  ASSERT_EQ(flat.vertex_count(), 9u);
  ASSERT_EQ(flat.triangle_count(), 3u);
  EXPECT_TRUE(flat.positions[3].isApprox(Eigen::Vector3f(0, 2, 5), 1e-6f));
  EXPECT_TRUE(flat.normals[3].isApprox(Eigen::Vector3f(0, 1, 0), 1e-6f));
  EXPECT_EQ(flat.triangles[1], (std::array<std::uint32_t, 3>{3, 4, 5}));
  EXPECT_EQ(flat.triangles[2], (std::array<std::uint32_t, 3>{6, 7, 8}));
  EXPECT_EQ(flat.uvs.size(), 9u);
  const auto age = flat.attribute("age"), light = flat.attribute("light");
  const auto order = flat.attribute(kAttributeOrder);
  EXPECT_EQ(age[0], 1.0f);
  EXPECT_EQ(age[3], 0.0f);  // the second mesh has no age
  EXPECT_EQ(light[3], 1.0f);
  EXPECT_EQ(light[8], 0.0f);
  EXPECT_EQ(order[2], 3.0f);
  EXPECT_EQ(order[8], 7.0f);  // 3 + the offset 4
  scene.meshes[1].normals.clear();
  EXPECT_TRUE(scene.flatten().normals.empty());  // a gap would shift them onto other vertices
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::uint32_t u32_at(const std::string& s, std::size_t at) {
  std::uint32_t x;
  std::memcpy(&x, s.data() + at, 4);
  return x;
}

nlohmann::json glb_json(const std::string& data) {
  return nlohmann::json::parse(data.substr(20, u32_at(data, 12)));
}

class InstancedFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fspm_inst_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(InstancedFiles, GlbStoresEachSubstructureOnce) {
  MeshOptions o;
  o.leaves = true;
  const InstancedMesh inst = mesh_instanced(three_level_plant(), o);
  write_glb(inst, path("plant.glb"));
  write_mesh(inst.flatten(), path("flat.glb"));
  const std::string data = slurp(path("plant.glb"));
  ASSERT_EQ(u32_at(data, 8), data.size());
  const auto doc = glb_json(data);
  ASSERT_EQ(doc["meshes"].size(), 3u);
  std::set<std::size_t> positions;
  std::size_t stored = 0;
  for (const auto& m : doc["meshes"]) {
    for (const auto& p : m["primitives"]) {
      positions.insert(p["attributes"]["POSITION"].get<std::size_t>());
      stored += doc["accessors"][p["indices"].get<std::size_t>()]["count"].get<std::size_t>() / 3;
    }
  }
  EXPECT_EQ(positions.size(), 3u);  // one vertex buffer per substructure
  EXPECT_EQ(stored, inst.stored_triangle_count());
  // Nodes: the root and one per occurrence; the represented triangles add up.
  std::size_t referencing = 0, represented = 0;
  for (const auto& n : doc["nodes"]) {
    if (!n.contains("mesh")) continue;
    ++referencing;
    for (const auto& p : doc["meshes"][n["mesh"].get<std::size_t>()]["primitives"]) {
      represented +=
          doc["accessors"][p["indices"].get<std::size_t>()]["count"].get<std::size_t>() / 3;
    }
  }
  EXPECT_EQ(referencing, 5u);
  EXPECT_EQ(represented, inst.triangle_count());
  EXPECT_EQ(doc["nodes"][0]["children"].size(), 5u);
  // The first lateral's node carries the translation (0, 0, 1) in its column-major matrix.
  const auto& m = doc["nodes"][2]["matrix"];
  ASSERT_EQ(m.size(), 16u);
  EXPECT_NEAR(m[12].get<double>(), 0.0, 1e-6);
  EXPECT_NEAR(m[14].get<double>(), 1.0, 1e-6);
  EXPECT_LT(data.size(), slurp(path("flat.glb")).size());
  // Formats without instancing get the explicit mesh.
  write_mesh(inst, path("plant.ply"));
  EXPECT_TRUE(fs::exists(path("plant.ply")));
  EXPECT_THROW(write_mesh(inst, path("plant.pvd")), ValueError);
}

TEST_F(InstancedFiles, SceneFileParsesAndResolvesPaths) {
  const std::string scene_path = path("forest.json");
  const SceneFile s = parse_scene(R"({"fspm_scene": 1, "instances": [
      {"file": "oak.ctree", "position": [1, 2, 0], "rotation_deg": 90, "scale": 2},
      {"file": "oak.ctree", "position": [5, 0, 0], "rotation_deg": [0, 0, 45]},
      {"file": "/abs/birch.tree", "age": 3},
      {"file": "sub/../oak.ctree"}]})",
                                  scene_path);
  ASSERT_EQ(s.instances.size(), 4u);
  ASSERT_EQ(s.sources.size(), 2u);  // oak (three times, once normalised) and birch
  EXPECT_EQ(s.sources[0].path, (dir_ / "oak.ctree").string());
  EXPECT_EQ(s.sources[1].path, "/abs/birch.tree");
  EXPECT_EQ(s.sources[1].age, 3.0);
  EXPECT_EQ(s.instances[3].source, 0u);
  // 90 degrees about z and scale 2: x -> 2 y.
  const Eigen::Vector3d x = s.instances[0].linear() * Eigen::Vector3d::UnitX();
  EXPECT_NEAR(x.y(), 2.0, 1e-12);
  EXPECT_NEAR(x.x(), 0.0, 1e-12);
  EXPECT_EQ(s.instances[1].rotation_deg.z(), 45.0);

  auto parse_error_for = [&](const std::string& text) {
    try {
      parse_scene(text, scene_path);
    } catch (const Error& e) {  // ParseError for bad JSON, ValueError for bad values
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(parse_error_for("{\"instances\": [\n  {\"file\": 1,}]}").find(":2:"),
            std::string::npos);  // bad JSON: line 2
  EXPECT_NE(parse_error_for(R"({"instances": [{"position": [0, 0, 0]}]})").find("file"),
            std::string::npos);
  EXPECT_NE(parse_error_for(R"({"instances": [{"file": "a", "scale": 0}]})").find("scale"),
            std::string::npos);
  EXPECT_NE(parse_error_for(R"({"instances": [{"file": "a", "colour": 1}]})").find("colour"),
            std::string::npos);
  EXPECT_NE(
      parse_error_for(R"({"instances": [{"file": "a", "position": [0, 0]}]})").find("position"),
      std::string::npos);
  EXPECT_NE(parse_error_for(R"({"trees": []})").find("trees"), std::string::npos);
  EXPECT_THROW(read_scene_file(path("missing.json")), IoError);
  EXPECT_TRUE(is_scene_path("a/B.JSON"));
  EXPECT_FALSE(is_scene_path("a.tree"));
}

// Fraction of pixels whose colours differ by more than `tolerance` in some channel.
double differing_fraction(const Image& a, const Image& b, int tolerance) {
  std::size_t n = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const auto *p = a.pixel(x, y), *q = b.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        if (std::abs(p[c] - q[c]) > tolerance) {
          ++n;
          break;
        }
      }
    }
  }
  return static_cast<double>(n) / (static_cast<double>(a.width) * a.height);
}

std::size_t bark_pixels(const Image& image) {
  std::size_t bark = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (p[0] > p[1] + 10 && p[1] > p[2] + 5) ++bark;
    }
  }
  return bark;
}

TEST(InstancedRender, GlyphInstancingLooksLikeTheFlattenedMesh) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  MeshOptions mo;
  mo.leaves = true;
  const InstancedMesh inst = mesh_instanced(three_level_plant(), mo);
  RenderOptions o;
  o.width = 240;
  o.height = 200;
  const Image instanced = render_scene(inst, o);
  const Image flat = render_mesh(inst.flatten(), o);
  ASSERT_EQ(instanced.width, flat.width);
  EXPECT_GT(bark_pixels(instanced), 200u);
  EXPECT_LT(differing_fraction(instanced, flat, 40), 0.01);
  o.color_by = "no_such_attribute";
  EXPECT_THROW(render_scene(inst, o), ValueError);
}

TEST(InstancedViewer, InstancedDrawsLookLikeTheFlattenedMesh) {
  if (!viewer_available() || !render_available()) GTEST_SKIP() << "built without viewer/VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  const fs::path dir = fs::temp_directory_path() / ("fspm_iview_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const InstancedMesh inst = mesh_instanced(three_level_plant(), {});
  ViewerOptions o;
  o.width = 240;
  o.height = 200;
  o.frames = 2;
  o.screenshot = (dir / "instanced.png").string();
  const ViewerStats stats = run_instanced_viewer({inst}, {0.0}, o);
  EXPECT_EQ(stats.triangles, inst.triangle_count());
  o.screenshot = (dir / "flat.png").string();
  run_viewer({inst.flatten()}, {0.0}, o);
  const Image a = read_image((dir / "instanced.png").string());
  const Image b = read_image((dir / "flat.png").string());
  EXPECT_GT(bark_pixels(a), 100u);
  EXPECT_LT(differing_fraction(a, b, 40), 0.01);
  // Colouring by order: each occurrence is coloured by its order in the plant, as in the
  // flattened mesh (not by the order within its substructure).
  o.color_by = kAttributeOrder;
  o.screenshot = (dir / "instanced_order.png").string();
  run_instanced_viewer({inst}, {0.0}, o);
  o.screenshot = (dir / "flat_order.png").string();
  run_viewer({inst.flatten()}, {0.0}, o);
  const Image c = read_image((dir / "instanced_order.png").string());
  const Image d = read_image((dir / "flat_order.png").string());
  EXPECT_GT(differing_fraction(c, a, 40), 0.005);  // the colours did change
  EXPECT_LT(differing_fraction(c, d, 40), 0.01);
  fs::remove_all(dir);
}

// Flattening checks the explicit mesh against the memory limit first: 100 000 instances of a
// 4-vertex quad are 400 000 vertices of 32 bytes (12.8 MB), above a limit of 1 MiB; 1 000
// instances (128 kB) are flattened.
TEST(InstancedMesh, FlattenStopsAtTheMemoryLimit) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  TriangleMesh quad;
  quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  quad.normals.assign(4, Eigen::Vector3f::UnitZ());
  quad.uvs.assign(4, Eigen::Vector2f::Zero());
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  quad.materials.assign(2, Material::kBark);
  InstancedMesh scene;
  scene.meshes.push_back(quad);
  scene.instances.resize(1000);
  EXPECT_EQ(scene.flatten().vertex_count(), 4000u);
  scene.instances.resize(100000);
  EXPECT_THROW(scene.flatten(), MemoryLimitError);
}

}  // namespace
}  // namespace fspm::graphics
