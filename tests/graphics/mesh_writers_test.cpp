#include "graphics/mesh_writers.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fspm/error.hpp"
#include "graphics/vtk_readback.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

class MeshWriters : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fspm_graphics_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    MeshOptions o;
    o.leaves = true;
    mesh_ = mesh_tree(testing::small_tree(), o);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
  TriangleMesh mesh_;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint32_t u32_at(const std::string& s, std::size_t at) {
  std::uint32_t x;
  std::memcpy(&x, s.data() + at, 4);
  return x;
}

TEST_F(MeshWriters, ObjAndMtl) {
  write_obj(mesh_, path("tree.obj"));
  std::ifstream in(path("tree.obj"));
  std::size_t v = 0, vn = 0, vt = 0, f = 0;
  std::vector<std::string> materials;
  std::string line, mtllib;
  Eigen::Vector3f first(0, 0, 0);
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if (tag == "v") {
      if (v == 0) s >> first.x() >> first.y() >> first.z();
      ++v;
    } else if (tag == "vn") {
      ++vn;
    } else if (tag == "vt") {
      ++vt;
    } else if (tag == "f") {
      ++f;
      std::string corner;
      int corners = 0;
      while (s >> corner) {
        const long idx = std::stol(corner.substr(0, corner.find('/')));
        ASSERT_GE(idx, 1);
        ASSERT_LE(static_cast<std::size_t>(idx), mesh_.vertex_count());
        ++corners;
      }
      EXPECT_EQ(corners, 3);
    } else if (tag == "usemtl") {
      std::string m;
      s >> m;
      materials.push_back(m);
    } else if (tag == "mtllib") {
      s >> mtllib;
    }
  }
  EXPECT_EQ(v, mesh_.vertex_count());
  EXPECT_EQ(vn, mesh_.vertex_count());
  EXPECT_EQ(vt, mesh_.vertex_count());
  EXPECT_EQ(f, mesh_.triangle_count());
  EXPECT_EQ(materials, (std::vector<std::string>{"bark", "leaf"}));
  EXPECT_TRUE(first.isApprox(mesh_.positions[0], 1e-5f));
  EXPECT_EQ(mtllib, "tree.mtl");
  const std::string mtl = slurp(path("tree.mtl"));
  EXPECT_NE(mtl.find("newmtl bark"), std::string::npos);
  EXPECT_NE(mtl.find("newmtl leaf"), std::string::npos);
}

TEST_F(MeshWriters, BinaryPly) {
  write_ply(mesh_, path("tree.ply"));
  const std::string data = slurp(path("tree.ply"));
  const std::size_t end = data.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  std::istringstream header(data.substr(0, end));
  std::string line;
  std::size_t nv = 0, nf = 0;
  std::vector<std::string> props;
  while (std::getline(header, line)) {
    std::istringstream s(line);
    std::string a, b, c;
    s >> a >> b >> c;
    if (a == "element" && b == "vertex") nv = std::stoul(c);
    if (a == "element" && b == "face") nf = std::stoul(c);
    if (a == "property" && b == "float") props.push_back(c);
  }
  EXPECT_NE(data.find("format binary_little_endian 1.0"), std::string::npos);
  ASSERT_EQ(nv, mesh_.vertex_count());
  ASSERT_EQ(nf, mesh_.triangle_count());
  ASSERT_EQ(props.size(), 8 + mesh_.attributes.size());
  const std::size_t light_col = std::find(props.begin(), props.end(), "light") - props.begin();
  ASSERT_LT(light_col, props.size());
  const char* body = data.data() + end + 11;
  const std::size_t stride = props.size() * 4;
  ASSERT_EQ(data.size() - (end + 11), nv * stride + nf * 14);
  const auto light = mesh_.attribute("light");
  for (std::size_t i = 0; i < nv; ++i) {
    float row[64];
    std::memcpy(row, body + i * stride, stride);
    ASSERT_FLOAT_EQ(row[0], mesh_.positions[i].x());
    ASSERT_FLOAT_EQ(row[2], mesh_.positions[i].z());
    ASSERT_FLOAT_EQ(row[light_col], light[i]);
  }
  const char* faces = body + nv * stride;
  for (std::size_t t = 0; t < nf; ++t) {
    ASSERT_EQ(faces[t * 14], 3);
    std::uint32_t idx[3];
    std::memcpy(idx, faces + t * 14 + 1, 12);
    ASSERT_EQ(idx[1], mesh_.triangles[t][1]);
  }
}

TEST_F(MeshWriters, VtpReadBackByVtk) {
  write_vtp(mesh_, path("tree.vtp"));
  if (!vtk_available()) GTEST_SKIP() << "built without VTK";
  const PolyDataInfo info = read_vtp_with_vtk(path("tree.vtp"));
  EXPECT_EQ(info.points, mesh_.vertex_count());
  EXPECT_EQ(info.polys, mesh_.triangle_count());
  EXPECT_EQ(info.triangles, mesh_.triangle_count());
  for (const auto& a : mesh_.attributes) {
    ASSERT_TRUE(info.point_data.count(a.name)) << a.name;
    EXPECT_EQ(info.point_data.at(a.name), a.values) << a.name;
  }
  EXPECT_EQ(info.point_components.at("Normals"), 3);
  EXPECT_EQ(info.point_components.at("TCoords"), 2);
  ASSERT_EQ(info.cell_data.at("material").size(), mesh_.triangle_count());
  EXPECT_FLOAT_EQ(info.cell_data.at("material").back(), 1.0f);  // last triangle is a leaf
  for (std::size_t i = 0; i < mesh_.vertex_count(); ++i) {
    ASSERT_FLOAT_EQ(info.points_xyz[3 * i + 1], mesh_.positions[i].y());
  }
}

TEST_F(MeshWriters, PvdGrowthSequence) {
  const TreeGraph tree = testing::small_tree();
  MeshOptions o;
  o.leaves = true;
  const auto frames = write_pvd(tree, o, {4.5, 0.5, 2.5}, path("growth.pvd"));
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_DOUBLE_EQ(frames[0].age, 0.5);
  EXPECT_DOUBLE_EQ(frames[2].age, 4.5);
  // Node counts by age: 0.5 -> trunk base only; 2.5 -> trunk and its leaf; 4.5 -> all.
  EXPECT_LT(frames[0].triangles, frames[1].triangles);
  EXPECT_LT(frames[1].triangles, frames[2].triangles);
  for (const auto& f : frames) {
    MeshOptions at = o;
    at.max_birth_time = f.age;
    const MeshCounts c = count_mesh(tree, at);
    EXPECT_EQ(f.triangles, c.triangles);
    ASSERT_TRUE(fs::exists(f.vtp_path));
    if (vtk_available()) {
      const PolyDataInfo info = read_vtp_with_vtk(f.vtp_path);
      EXPECT_EQ(info.points, c.vertices);
      EXPECT_EQ(info.polys, c.triangles);
    }
  }
  const std::string pvd = slurp(path("growth.pvd"));
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0.5\" group=\"\" part=\"0\" file=\"growth_0000.vtp\""),
            std::string::npos);
  EXPECT_NE(pvd.find("file=\"growth_0002.vtp\""), std::string::npos);
  EXPECT_THROW(write_pvd(tree, o, {}, path("none.pvd")), ValueError);
}

TEST_F(MeshWriters, GlbReadBack) {
  write_glb(mesh_, path("tree.glb"));
  const std::string data = slurp(path("tree.glb"));
  ASSERT_GE(data.size(), 20u);
  EXPECT_EQ(u32_at(data, 0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(u32_at(data, 4), 2u);
  EXPECT_EQ(u32_at(data, 8), data.size());
  const std::uint32_t json_len = u32_at(data, 12);
  EXPECT_EQ(u32_at(data, 16), 0x4E4F534Au);  // "JSON"
  EXPECT_EQ(json_len % 4, 0u);
  const auto doc = nlohmann::json::parse(data.substr(20, json_len));
  const std::size_t bin_at = 20 + json_len;
  const std::uint32_t bin_len = u32_at(data, bin_at);
  EXPECT_EQ(u32_at(data, bin_at + 4), 0x004E4942u);  // "BIN\0"
  EXPECT_EQ(bin_len, doc["buffers"][0]["byteLength"].get<std::uint32_t>());
  const char* bin = data.data() + bin_at + 8;

  EXPECT_EQ(doc["asset"]["version"], "2.0");
  const auto& prims = doc["meshes"][0]["primitives"];
  ASSERT_EQ(prims.size(), 2u);
  auto accessor_data = [&](std::size_t acc) {
    const auto& a = doc["accessors"][acc];
    const auto& v = doc["bufferViews"][a["bufferView"].get<std::size_t>()];
    return std::make_pair(bin + v["byteOffset"].get<std::size_t>(), a["count"].get<std::size_t>());
  };
  std::size_t triangles = 0;
  for (const auto& p : prims) {
    triangles += doc["accessors"][p["indices"].get<std::size_t>()]["count"].get<std::size_t>() / 3;
  }
  EXPECT_EQ(triangles, mesh_.triangle_count());
  const auto& leaf_idx = doc["accessors"][prims[1]["indices"].get<std::size_t>()];
  EXPECT_EQ(leaf_idx["count"].get<std::size_t>(), 3 * mesh_.triangle_count(Material::kLeaf));
  EXPECT_EQ(doc["materials"][prims[1]["material"].get<std::size_t>()]["name"], "leaf");

  const auto [pos, count] = accessor_data(prims[0]["attributes"]["POSITION"].get<std::size_t>());
  ASSERT_EQ(count, mesh_.vertex_count());
  for (std::size_t i = 0; i < count; ++i) {
    float p[3];
    std::memcpy(p, pos + 12 * i, 12);
    ASSERT_FLOAT_EQ(p[0], mesh_.positions[i].x());
    ASSERT_FLOAT_EQ(p[2], mesh_.positions[i].z());
  }
  const auto& pos_acc = doc["accessors"][prims[0]["attributes"]["POSITION"].get<std::size_t>()];
  EXPECT_FLOAT_EQ(pos_acc["max"][2].get<float>(), mesh_.bbox_max().z());
  ASSERT_TRUE(prims[0]["attributes"].contains("_LIGHT"));
  const auto [light, light_count] =
      accessor_data(prims[0]["attributes"]["_LIGHT"].get<std::size_t>());
  ASSERT_EQ(light_count, mesh_.vertex_count());
  const auto expected = mesh_.attribute("light");
  for (std::size_t i = 0; i < light_count; ++i) {
    float x;
    std::memcpy(&x, light + 4 * i, 4);
    ASSERT_FLOAT_EQ(x, expected[i]);
  }
  // Indices of the bark primitive reproduce the first triangle.
  const auto [idx, n_idx] = accessor_data(prims[0]["indices"].get<std::size_t>());
  ASSERT_GE(n_idx, 3u);
  std::uint32_t t0[3];
  std::memcpy(t0, idx, 12);
  EXPECT_EQ(t0[2], mesh_.triangles[0][2]);
}

TEST_F(MeshWriters, ByExtensionAndBadPaths) {
  EXPECT_EQ(mesh_format_for("a/b.GLB"), MeshFormat::kGlb);
  EXPECT_THROW(mesh_format_for("tree.stl"), ValueError);
  EXPECT_THROW(write_mesh(mesh_, path("tree.pvd")), ValueError);
  const std::string bad = path("missing_dir/tree.glb");
  EXPECT_THROW(write_mesh(mesh_, bad), IoError);
  EXPECT_FALSE(fs::exists(bad));
  write_mesh(mesh_, path("t.ply"));
  EXPECT_TRUE(fs::exists(path("t.ply")));
}

// glTF 2.0 (section 3.7.2.1) makes NORMAL and TEXCOORD_0 optional: a mesh without them (as the
// HTML report writes its trees) leaves them out, and the file still adds up: the binary chunk
// holds exactly the accessors' bytes.
TEST_F(MeshWriters, GlbWithoutNormalsAndUvsLeavesThemOut) {
  TriangleMesh bare = mesh_;
  bare.normals.clear();
  bare.uvs.clear();
  write_glb(bare, path("bare.glb"));
  const std::string data = slurp(path("bare.glb"));
  EXPECT_EQ(u32_at(data, 8), data.size());
  const std::uint32_t json_len = u32_at(data, 12);
  const auto doc = nlohmann::json::parse(data.substr(20, json_len));
  const auto& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
  EXPECT_TRUE(attributes.contains("POSITION"));
  EXPECT_FALSE(attributes.contains("NORMAL"));
  EXPECT_FALSE(attributes.contains("TEXCOORD_0"));
  // Positions (12 bytes) and each attribute (4 bytes) per vertex, 4 bytes per index.
  const std::size_t nv = bare.vertex_count();
  const std::size_t expected = nv * (12 + 4 * bare.attributes.size()) + 12 * bare.triangle_count();
  EXPECT_EQ(doc["buffers"][0]["byteLength"].get<std::size_t>(), expected);
}

TEST_F(MeshWriters, EmptyMeshGlbIsValid) {
  write_glb(TriangleMesh{}, path("empty.glb"));
  const std::string data = slurp(path("empty.glb"));
  EXPECT_EQ(u32_at(data, 8), data.size());
  const auto doc = nlohmann::json::parse(data.substr(20, u32_at(data, 12)));
  EXPECT_FALSE(doc.contains("meshes"));
}

}  // namespace
}  // namespace fspm::graphics
