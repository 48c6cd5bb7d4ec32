// The reader registry: one reader for every file kind, and files written by hand read as what
// they hold.
#include "io/input_registry.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fspm/error.hpp"
#include "io/input_kind.hpp"

namespace fspm::io {
namespace {

std::string temp_file(const std::string& name, const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

constexpr const char* kPly =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\n";

TEST(InputRegistry, EveryKindHasAReader) {
  for (const FileKindInfo& info : file_kinds()) {
    const InputReader* reader = find_input_reader(info.kind);
    ASSERT_NE(reader, nullptr) << info.name;
    EXPECT_EQ(reader->kind, info.kind);
  }
  EXPECT_EQ(find_input_reader(FileKind::kUnknown), nullptr);
}

TEST(InputRegistry, PlyWithFacesIsAMeshWithoutAPointSet) {
  const std::string points = temp_file(
      "fspm_registry_points.ply", std::string(kPly) + "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n");
  const InputData a = read_input(points);
  ASSERT_TRUE(std::holds_alternative<scans::PointSet>(a));
  EXPECT_EQ(std::get<scans::PointSet>(a).points.size(), 4u);
  const std::string quad = temp_file(
      "fspm_registry_quad.ply",
      std::string(kPly) +
          "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n"
          "1 1 0\n0 1 0\n4 0 1 2 3\n");
  const InputData b = read_input(quad);
  ASSERT_TRUE(std::holds_alternative<graphics::TriangleMesh>(b));
  // A quad is a fan of two triangles.
  EXPECT_EQ(std::get<graphics::TriangleMesh>(b).triangle_count(), 2u);
  std::filesystem::remove(points);
  std::filesystem::remove(quad);
}

TEST(InputRegistry, UnknownAndMissingFiles) {
  const std::string unknown = temp_file("fspm_registry_notes.bin", "nothing fspm reads\n");
  EXPECT_THROW((void)read_input(unknown), ValueError);
  std::filesystem::remove(unknown);
  EXPECT_THROW((void)read_input(unknown), IoError);
}

TEST(InputKind, GraphicsInputsByKind) {
  EXPECT_EQ(input_kind("plant.CTREE"), InputKind::kCompressed);
  EXPECT_EQ(input_kind("plant.toml"), InputKind::kPlant);
  EXPECT_EQ(input_kind("scene.json"), InputKind::kScene);
  EXPECT_EQ(input_kind("growth.pvd"), InputKind::kPvd);
  EXPECT_EQ(input_kind("plant.l"), InputKind::kLsystem);
  EXPECT_EQ(input_kind("crown.gltf"), InputKind::kMesh);
  EXPECT_EQ(input_kind("tree.nwk"), InputKind::kTree);
  EXPECT_EQ(input_kind("missing_and_unknown"), InputKind::kTree);
}

}  // namespace
}  // namespace fspm::io
