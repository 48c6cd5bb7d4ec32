// glTF 2.0 mesh input through the one mesh entry point (scans/mesh_file.hpp): hand-made files whose
// counts and bounding boxes are known in closed form, node transforms, names as groups, errors,
// and the grouped-mesh skeleton (Reynolds et al. 2011, 3.1) of the same branches as glTF nodes
// and as OBJ groups.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "fspm/error.hpp"
#include "scans/gltf_reader.hpp"
#include "scans/grouped_mesh_skeleton.hpp"
#include "scans/mesh_file.hpp"
#include "scans/point_set_file.hpp"
#include "tests/scans/gltf_test_file.hpp"

namespace fspm::scans {
namespace {

using test::GltfPart;

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("fspm_gltf_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

void expect_box(const GroupedMesh& m, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Eigen::Vector3d a = m.vertices.at(0), b = m.vertices.at(0);
  for (const Eigen::Vector3d& p : m.vertices) a = a.cwiseMin(p), b = b.cwiseMax(p);
  EXPECT_LT((a - lo).norm(), 1e-6) << a.transpose();
  EXPECT_LT((b - hi).norm(), 1e-6) << b.transpose();
}

std::size_t distinct_positions(const GroupedMesh& m) {
  std::set<std::array<double, 3>> s;
  for (const Eigen::Vector3d& p : m.vertices) s.insert({p.x(), p.y(), p.z()});
  return s.size();
}

// Translation * scale (glTF 2.0 sec. 3.5.3): the unit cube scaled by 2 then moved by (1, 2, 3).
TEST(GltfReader, UnitCubeMovedByItsNodeTransform) {
  const std::string path = temp_path("cube.gltf");
  GltfPart cube = test::unit_cube("Cube", "cube_mesh");
  cube.transform = {{"translation", {1, 2, 3}}, {"scale", {2, 2, 2}}};
  test::write_gltf(path, {cube});
  ASSERT_TRUE(is_mesh_file(path));
  const GroupedMesh m = read_mesh_file(path);
  EXPECT_EQ(m.faces.size(), 12u);
  EXPECT_EQ(distinct_positions(m), 8u);
  for (const auto& f : m.faces) EXPECT_EQ(f.size(), 3u);
  ASSERT_EQ(m.group_names.size(), 1u);
  EXPECT_EQ(m.group_names[0], "Cube");
  expect_box(m, {1, 2, 3}, {3, 4, 5});
  // As a point set: the vertices.
  EXPECT_EQ(read_point_set(path).points.size(), m.vertices.size());
}

// Materials and vertex colours (glTF 2.0 sec. 3.7.2.1 COLOR_0, sec. 3.9 materials): two cubes,
// the first "bark" without colours, the second "leaf" with one colour per corner, which the reader
// gives back per face and per vertex (NaN for the vertices of the mesh without colours).
TEST(GltfReader, MaterialsAndColoursPerFaceAndVertex) {
  const std::string path = temp_path("materials.gltf");
  GltfPart second = test::unit_cube("Second", "second_mesh");
  for (float& x : second.positions) x += 2.0f;
  auto [g, bin] = test::gltf_of({test::unit_cube("First", "first_mesh"), second});
  std::vector<float> rgb;
  for (int v = 0; v < 8; ++v) rgb.insert(rgb.end(), {0.1f * v, 0.5f, 1.0f - 0.1f * v});
  g["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", 4 * rgb.size()}});
  bin.append(reinterpret_cast<const char*>(rgb.data()), 4 * rgb.size());
  g["accessors"].push_back({{"bufferView", g["bufferViews"].size() - 1},
                            {"componentType", 5126},
                            {"count", 8},
                            {"type", "VEC3"}});
  g["buffers"][0]["byteLength"] = bin.size();
  g["materials"] = {{{"name", "bark"}}, {{"name", "leaf"}}};
  g["meshes"][0]["primitives"][0]["material"] = 0;
  g["meshes"][1]["primitives"][0]["material"] = 1;
  g["meshes"][1]["primitives"][0]["attributes"]["COLOR_0"] = g["accessors"].size() - 1;
  g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + test::base64(bin);
  std::ofstream(path, std::ios::binary) << g.dump();

  const GltfMesh m = read_gltf(path);
  ASSERT_EQ(m.mesh.faces.size(), 24u);
  ASSERT_EQ(m.face_material.size(), 24u);
  for (std::size_t f = 0; f < 24; ++f) {
    ASSERT_LT(m.face_material[f], m.material_names.size());
    EXPECT_EQ(m.material_names[m.face_material[f]], f < 12 ? "bark" : "leaf") << f;
  }
  ASSERT_EQ(m.mesh.vertices.size(), 16u);
  EXPECT_EQ(m.normals.size(), 16u);
  ASSERT_EQ(m.colours.size(), 16u);
  for (std::size_t v = 0; v < 8; ++v) EXPECT_TRUE(m.colours[v].array().isNaN().all()) << v;
  for (std::size_t v = 8; v < 16; ++v) {
    // The second cube's vertex v - 8 sits at its corner, moved by (2, 2, 2).
    const Eigen::Vector3d p = m.mesh.vertices[v] - Eigen::Vector3d::Constant(2.0);
    const auto corner = static_cast<int>(std::lround(p.x() + 2 * p.y() + 4 * p.z()));
    EXPECT_NEAR(m.colours[v].x(), 0.1f * corner, 1e-6f) << v;
    EXPECT_NEAR(m.colours[v].y(), 0.5f, 1e-6f) << v;
    EXPECT_NEAR(m.colours[v].z(), 1.0f - 0.1f * corner, 1e-6f) << v;
  }
  std::filesystem::remove(path);
}

// A parent turned 90 degrees about z, its child moved by (1, 0, 0): p -> Rz(90) (p + x), so the
// unit cube goes to [-1, 0] x [1, 2] x [0, 1]. The parent has no mesh and makes no group.
TEST(GltfReader, BinaryGlbChainsParentAndChildTransforms) {
  const std::string path = temp_path("chain.glb");
  GltfPart cube = test::unit_cube("Child", "cube_mesh");
  cube.transform = {{"translation", {1, 0, 0}}};
  const double s = std::sqrt(0.5);
  test::write_glb(path, {cube}, {{"rotation", {0, 0, s, s}}});  // quaternion x y z w
  const GroupedMesh m = read_mesh_file(path);
  EXPECT_EQ(m.faces.size(), 12u);
  EXPECT_EQ(distinct_positions(m), 8u);
  ASSERT_EQ(m.group_names.size(), 1u);
  EXPECT_EQ(m.group_names[0], "Child");
  expect_box(m, {-1, 1, 0}, {0, 2, 1});
}

TEST(GltfReader, NodeWithoutNameTakesItsMeshName) {
  const std::string path = temp_path("unnamed.glb");
  GltfPart a = test::unit_cube("", "Branch7");
  GltfPart b = test::unit_cube("Leaf", "leaf_mesh");
  b.transform = {{"translation", {0, 0, 5}}};
  test::write_glb(path, {a, b});
  const GroupedMesh m = read_mesh_file(path);
  ASSERT_EQ(m.group_names.size(), 2u);
  EXPECT_EQ(m.group_names[0], "Branch7");
  EXPECT_EQ(m.group_names[1], "Leaf");
  ASSERT_EQ(m.face_group.size(), 24u);
  EXPECT_EQ(m.face_group[0], 0u);
  EXPECT_EQ(m.face_group[23], 1u);
  expect_box(m, {0, 0, 0}, {1, 1, 6});
}

TEST(GltfReader, ErrorsNameTheFile) {
  const std::string missing = temp_path("missing.glb");
  try {
    read_mesh_file(missing);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const IoError& e) {
    EXPECT_EQ(e.file(), missing);
  }
  const std::string broken = temp_path("broken.gltf");
  std::ofstream(broken) << R"({"asset": {"version": "2.0"}, "meshes": [)";
  try {
    read_mesh_file(broken);
    ADD_FAILURE() << "no error for a malformed file";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), broken);
  }
  const std::string points = temp_path("points.glb");
  GltfPart p = test::unit_cube("Points", "points");
  p.mode = 0;  // POINTS
  test::write_glb(points, {p});
  try {
    read_mesh_file(points);
    ADD_FAILURE() << "no error for a file without triangles";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), points);
  }
}

// A square cross-section of side w centred at c, normal to z: four corners.
std::array<Eigen::Vector3d, 4> square(const Eigen::Vector3d& c, double w) {
  const double h = w / 2;
  return {c + Eigen::Vector3d(-h, -h, 0), c + Eigen::Vector3d(h, -h, 0),
          c + Eigen::Vector3d(h, h, 0), c + Eigen::Vector3d(-h, h, 0)};
}

struct Branch {
  std::string name;
  std::vector<std::array<Eigen::Vector3d, 4>> sections;
};

// A trunk of five sections along z and two branches leaving it near z = 2 and z = 3, with
// coordinates that single precision holds exactly.
std::vector<Branch> three_branches() {
  std::vector<Branch> b{{"Trunk1", {}}, {"Branch1", {}}, {"Branch2", {}}};
  for (int k = 0; k <= 4; ++k) b[0].sections.push_back(square({0, 0, k * 1.0}, 0.5));
  for (int k = 1; k <= 3; ++k) b[1].sections.push_back(square({0.5 * k, 0, 2.0 + 0.25 * k}, 0.125));
  for (int k = 1; k <= 2; ++k)
    b[2].sections.push_back(square({0, -0.5 * k, 2.75 + 0.5 * k}, 0.125));
  return b;
}

// OBJ: a group per branch, a quad per section.
std::string obj_of(const std::vector<Branch>& branches) {
  std::ostringstream obj;
  int next = 1;
  for (const Branch& b : branches) {
    obj << "g " << b.name << '\n';
    for (const auto& s : b.sections) {
      for (const Eigen::Vector3d& p : s)
        obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
      obj << "f " << next << ' ' << next + 1 << ' ' << next + 2 << ' ' << next + 3 << '\n';
      next += 4;
    }
  }
  return obj.str();
}

// glTF: a node per branch, each section split into two triangles along a diagonal.
std::vector<GltfPart> gltf_of(const std::vector<Branch>& branches) {
  std::vector<GltfPart> parts;
  for (const Branch& b : branches) {
    GltfPart p{b.name, b.name + "_mesh", {}, {}};
    for (const auto& s : b.sections) {
      const auto first = static_cast<std::uint32_t>(p.positions.size() / 3);
      for (const Eigen::Vector3d& q : s) {
        p.positions.insert(p.positions.end(), {static_cast<float>(q.x()), static_cast<float>(q.y()),
                                               static_cast<float>(q.z())});
      }
      p.indices.insert(p.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    parts.push_back(std::move(p));
  }
  return parts;
}

TEST(GltfReader, BranchNodesGiveTheSkeletonOfObjGroups) {
  const std::vector<Branch> branches = three_branches();
  const std::string glb = temp_path("branches.glb");
  test::write_glb(glb, gltf_of(branches));
  const GroupedMesh from_gltf = read_mesh_file(glb);
  EXPECT_EQ(from_gltf.faces.size(), 2u * (5 + 3 + 2));
  const TreeGraph g = grouped_mesh_skeleton(from_gltf, glb);
  const TreeGraph o = grouped_mesh_skeleton(parse_obj_mesh(obj_of(branches), "b.obj"), "b.obj");
  ASSERT_EQ(g.size(), 4u + 3u + 2u);
  ASSERT_EQ(o.size(), g.size());
  for (NodeId i = 0; i < g.size(); ++i) {
    EXPECT_EQ(g.parent(i), o.parent(i)) << i;
    EXPECT_EQ(g.order(i), o.order(i)) << i;
    EXPECT_LT((g.start(i) - o.start(i)).norm(), 1e-12) << i;
    EXPECT_LT((g.end(i) - o.end(i)).norm(), 1e-12) << i;
    EXPECT_NEAR(g.radius(i), o.radius(i), 1e-12) << i;
  }
  // Closed form: trunk bones end at the section midpoints z = 1..4, radius half the side (the
  // inscribed radius of a square); Branch1 hangs at the trunk node ending at z = 2 (id 1),
  // Branch2 at the one ending at z = 3 (id 2).
  EXPECT_TRUE(g.end(3).isApprox(Eigen::Vector3d(0, 0, 4)));
  EXPECT_NEAR(g.radius(0), 0.25, 1e-12);
  EXPECT_EQ(g.parent(4), 1u);
  EXPECT_EQ(g.parent(7), 2u);
  EXPECT_EQ(g.order(7), 1);
  EXPECT_NEAR(g.radius(8), 0.0625, 1e-12);
}

}  // namespace
}  // namespace fspm::scans
