// The one table of file kinds: extensions in any case, and the first bytes the format
// specifications fix (PLY header line, GLB header, LAS public header block, PCD header comment)
// or fspm's own magics, for files whose extension names no kind.
#include "fspm/file_kind.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"

namespace fspm {
namespace {

TEST(FileKind, ExtensionsInAnyCase) {
  EXPECT_EQ(file_kind_by_extension("a/b/tree.TREEB"), FileKind::kTreeBinary);
  EXPECT_EQ(file_kind_by_extension("plant.ctree"), FileKind::kCtree);
  EXPECT_EQ(file_kind_by_extension("scan.Las"), FileKind::kLas);
  EXPECT_EQ(file_kind_by_extension("scan.laz"), FileKind::kLas);
  EXPECT_EQ(file_kind_by_extension("points.csv"), FileKind::kXyz);
  EXPECT_EQ(file_kind_by_extension("crown.GLB"), FileKind::kGlb);
  EXPECT_EQ(file_kind_by_extension("noextension"), FileKind::kUnknown);
  EXPECT_EQ(file_kind_by_extension("notes.bin"), FileKind::kUnknown);
  EXPECT_EQ(file_kind_for_extension(".Obj"), FileKind::kObj);
}

TEST(FileKind, TableExtensionTellsApartTheExtensionsOfOneKind) {
  EXPECT_EQ(table_extension("scan.LAZ"), ".laz");
  EXPECT_EQ(table_extension("scan.las"), ".las");
  EXPECT_EQ(table_extension("dir.v2/points.Csv"), ".csv");
  EXPECT_EQ(table_extension("notes.bin"), "");
  EXPECT_EQ(table_extension("noextension"), "");
}

TEST(FileKind, EveryKindHasOneRowAndItsExtensionsAreItsOwn) {
  for (const FileKindInfo& info : file_kinds()) {
    EXPECT_EQ(&file_kind_info(info.kind), &info);
    ASSERT_FALSE(info.extensions[0].empty()) << info.name;
    for (std::string_view e : info.extensions) {
      if (!e.empty()) {
        EXPECT_EQ(file_kind_for_extension(e), info.kind) << e;
      }
    }
  }
}

TEST(FileKind, FirstBytesOfEachFormat) {
  EXPECT_EQ(file_kind_by_content("ply\nformat ascii 1.0\n"), FileKind::kPly);
  EXPECT_EQ(file_kind_by_content("ply\r\nformat ascii 1.0\r\n"), FileKind::kPly);
  EXPECT_EQ(file_kind_by_content("plywood\n"), FileKind::kUnknown);
  EXPECT_EQ(file_kind_by_content(std::string("glTF\x02\0\0\0", 8)), FileKind::kGlb);
  EXPECT_EQ(file_kind_by_content("LASF\0\0"), FileKind::kLas);
  EXPECT_EQ(file_kind_by_content("# .PCD v0.7 - Point Cloud Data\nVERSION 0.7\n"), FileKind::kPcd);
  EXPECT_EQ(file_kind_by_content("VERSION 0.7\nFIELDS x y z\n"), FileKind::kPcd);
  EXPECT_EQ(file_kind_by_content("FSPMTREB\x01"), FileKind::kTreeBinary);
  EXPECT_EQ(file_kind_by_content("FSPMCTRE\x02"), FileKind::kCtree);
  EXPECT_EQ(file_kind_by_content("FSPMCLU3"), FileKind::kClusters);
  EXPECT_EQ(file_kind_by_content("fspm-tree 1\n"), FileKind::kTreeText);
  EXPECT_EQ(file_kind_by_content("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\">"),
            FileKind::kPvd);
  EXPECT_EQ(file_kind_by_content("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\">"),
            FileKind::kVtp);
  EXPECT_EQ(file_kind_by_content("0 0 0\n1 1 1\n"), FileKind::kUnknown);
  EXPECT_EQ(file_kind_by_content(""), FileKind::kUnknown);
}

TEST(FileKind, TheExtensionDecidesAndTheBytesOnlyWithoutOne) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string bare = (dir / "fspm_file_kind_bare").string();
  const std::string named = (dir / "fspm_file_kind_named.xyz").string();
  std::ofstream(bare, std::ios::binary) << "ply\nformat ascii 1.0\n";
  std::ofstream(named, std::ios::binary) << "ply\nformat ascii 1.0\n";
  EXPECT_EQ(file_kind(bare), FileKind::kPly);
  EXPECT_EQ(file_kind(named), FileKind::kXyz);
  EXPECT_EQ(file_kind((dir / "fspm_file_kind_missing").string()), FileKind::kUnknown);
  std::filesystem::remove(bare);
  std::filesystem::remove(named);
}

// A tree file without extension is read in the format its magic tells; written, it still needs
// an extension or a format (the bytes of an old file at the path do not choose).
TEST(FileKind, TreeFilesWithoutExtensionAreReadByTheirMagic) {
  TreeGraph tree;
  NodeData d;
  d.end = {0.0, 0.0, 1.0};
  const NodeId root = tree.add_node(kNoNode, d);
  d.start = d.end;
  d.end = {0.0, 0.5, 1.5};
  tree.add_node(root, d);
  const auto dir = std::filesystem::temp_directory_path();
  for (const char* format : {"tree", "treeb"}) {
    const std::string bare = (dir / (std::string("fspm_file_kind_tree_") + format)).string();
    write_tree_file(tree, bare, format);
    const TreeGraph back = read_tree_file(bare);
    ASSERT_EQ(back.size(), 2u) << format;
    EXPECT_EQ(back.parent(1), 0u);
    EXPECT_DOUBLE_EQ(back.end(1).y(), 0.5);
    EXPECT_THROW(write_tree_file(tree, bare), ValueError);
    std::filesystem::remove(bare);
  }
}

TEST(FileKind, FamiliesAndWrittenMeshFormats) {
  EXPECT_TRUE(is_tree_kind(FileKind::kMtg));
  EXPECT_FALSE(is_tree_kind(FileKind::kCtree));
  EXPECT_EQ(tree_format_of_kind(FileKind::kTreeBinary), "treeb");
  EXPECT_TRUE(is_polygon_mesh_kind(FileKind::kPly));
  EXPECT_FALSE(is_grouped_mesh_kind(FileKind::kPly));
  EXPECT_TRUE(is_point_set_kind(FileKind::kGlb));
  EXPECT_FALSE(is_point_set_kind(FileKind::kVtp));
  EXPECT_EQ(written_mesh_format(FileKind::kVtp), MeshFormat::kVtp);
  EXPECT_EQ(written_mesh_format(FileKind::kGltf), std::nullopt);
  // mesh_format_for asks the same table.
  EXPECT_EQ(mesh_format_for("out/TREE.GLB"), MeshFormat::kGlb);
  EXPECT_THROW(mesh_format_for("tree.gltf"), ValueError);
}

}  // namespace
}  // namespace fspm
