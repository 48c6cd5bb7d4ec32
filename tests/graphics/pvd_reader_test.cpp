// Reading growth sequences back for the viewer: the .pvd collection and its .vtp meshes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "fspm/error.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/vtk_readback.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

class PvdReader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fspm_pvdread_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
  }
  fs::path dir_;
};

TEST_F(PvdReader, CollectionStepsSortedWithResolvedPaths) {
  write("seq.pvd",
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n"
        "  <DataSet timestep=\"2.5\" group=\"\" part=\"0\" file=\"b.vtp\"/>\n"
        "  <DataSet part='0' timestep='0.5' file='sub/a.vtp'/>\n"
        "  <DataSet timestep=\"7\" file=\"/abs/c.vtp\"/>\n</Collection>\n</VTKFile>\n");
  const auto steps = read_pvd_file(path("seq.pvd"));
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[0].time, 0.5);
  EXPECT_EQ(steps[0].path, (dir_ / "sub/a.vtp").string());
  EXPECT_EQ(steps[1].time, 2.5);
  EXPECT_EQ(steps[1].path, (dir_ / "b.vtp").string());
  EXPECT_EQ(steps[2].path, "/abs/c.vtp");
}

TEST_F(PvdReader, MalformedCollectionsAreParseErrors) {
  write("empty.pvd", "<VTKFile type=\"Collection\"><Collection></Collection></VTKFile>");
  EXPECT_THROW(read_pvd_file(path("empty.pvd")), ParseError);
  write("nofile.pvd", "<VTKFile type=\"Collection\"><Collection>\n<DataSet timestep=\"1\"/>");
  try {
    read_pvd_file(path("nofile.pvd"));
    ADD_FAILURE() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
  }
  write("badtime.pvd", "<VTKFile type=\"Collection\"><DataSet timestep=\"x\" file=\"a.vtp\"/>");
  EXPECT_THROW(read_pvd_file(path("badtime.pvd")), ParseError);
  write("other.pvd", "<html></html>");
  EXPECT_THROW(read_pvd_file(path("other.pvd")), ParseError);
  EXPECT_THROW(read_pvd_file(path("missing.pvd")), IoError);
}

TEST_F(PvdReader, WrittenSequenceReadsBackMeshByMesh) {
  if (!vtk_available()) GTEST_SKIP() << "built without VTK";
  const TreeGraph tree = testing::small_tree();
  MeshOptions o;
  o.leaves = true;
  const auto frames = write_pvd(tree, o, {1.0, 4.5}, path("growth.pvd"));
  const auto steps = read_pvd_file(path("growth.pvd"));
  ASSERT_EQ(steps.size(), frames.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].time, frames[i].age);
    o.max_birth_time = frames[i].age;
    const TriangleMesh original = mesh_tree(tree, o);
    const TriangleMesh back = read_vtp_mesh(steps[i].path);
    ASSERT_EQ(back.vertex_count(), original.vertex_count());
    ASSERT_EQ(back.triangle_count(), original.triangle_count());
    EXPECT_EQ(back.triangle_count(Material::kLeaf), original.triangle_count(Material::kLeaf));
    EXPECT_EQ(back.triangles, original.triangles);
    for (std::size_t v = 0; v < back.vertex_count(); ++v) {
      ASSERT_TRUE(back.positions[v].isApprox(original.positions[v])) << v;
      ASSERT_TRUE(back.normals[v].isApprox(original.normals[v])) << v;
    }
    for (const auto& name : original.attribute_names()) {
      const auto a = back.attribute(name), b = original.attribute(name);
      EXPECT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << name;
    }
  }
  EXPECT_THROW(read_vtp_mesh(path("none.vtp")), IoError);
}

}  // namespace
}  // namespace fspm::graphics
