// Point-set and mesh readers: values from hand-written files, errors naming line or byte.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "fspm/error.hpp"
#include "scans/obj_reader.hpp"
#include "scans/pcd_reader.hpp"
#include "scans/ply_reader.hpp"
#include "scans/point_set_file.hpp"
#include "scans/point_set_writer.hpp"
#include "scans/xyz_reader.hpp"

namespace fspm::scans {
namespace {

std::string temp_file(const std::string& name, const std::string& content) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("fspm_scans_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(path, std::ios::binary) << content;
  return path.string();
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <class T>
void append(std::string& s, T v, bool big_endian = false) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (big_endian) std::reverse(b, b + sizeof(T));
  s.append(b, sizeof(T));
}

TEST(PlyReader, AsciiWithFacesAndExtraProperties) {
  const std::string text =
      "ply\nformat ascii 1.0\ncomment test\nelement vertex 3\nproperty float nx\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n"
      "9 1 2 3\n9 4 5 6\n9 -1 0.5 1e2\n3 0 1 2\n";
  const PointSet ps = parse_ply_points(text, "a.ply");
  ASSERT_EQ(ps.points.size(), 3u);
  EXPECT_EQ(ps.points[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(ps.points[2], Eigen::Vector3d(-1, 0.5, 100));
}

TEST(PlyReader, BinaryLittleAndBigEndianGiveTheSamePoints) {
  for (bool big : {false, true}) {
    std::string data = std::string("ply\nformat ") +
                       (big ? "binary_big_endian" : "binary_little_endian") +
                       " 1.0\nelement vertex 2\nproperty double x\nproperty double y\n"
                       "property double z\nproperty uchar red\nend_header\n";
    for (double v : {1.5, -2.0, 3.25}) append(data, v, big);
    append<std::uint8_t>(data, 7);
    for (double v : {4.0, 5.0, 6.0}) append(data, v, big);
    append<std::uint8_t>(data, 8);
    const PointSet ps = parse_ply_points(data, "b.ply");
    ASSERT_EQ(ps.points.size(), 2u);
    EXPECT_EQ(ps.points[0], Eigen::Vector3d(1.5, -2.0, 3.25));
    EXPECT_EQ(ps.points[1], Eigen::Vector3d(4, 5, 6));
  }
}

TEST(PlyReader, TruncatedBinaryNamesTheByteOffset) {
  std::string data =
      "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
      "property float y\nproperty float z\nend_header\n";
  const std::size_t header = data.size();
  for (float v : {1.0f, 2.0f, 3.0f, 4.0f}) append(data, v);
  try {
    parse_ply_points(data, "c.ply");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "c.ply");
    EXPECT_NE(e.message().find("byte " + std::to_string(header + 16)), std::string::npos)
        << e.what();
  }
}

// Found by the point-set fuzzer: a header whose last line has no newline puts the data past the
// end of the file, which the bulk reader must refuse rather than read before the data starts.
TEST(PlyReader, HeaderEndingWithoutNewlineHasNoData) {
  const std::string data =
      "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\n"
      "property float y\nproperty float z\nend_header y@";
  EXPECT_THROW(parse_ply_points(data, "cut.ply"), ParseError);
  EXPECT_THROW(parse_ply_mesh(data, "cut.ply"), ParseError);
}

TEST(PlyReader, BadAsciiValueNamesTheLine) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3\n1 two 3\n";
  try {
    parse_ply_points(text, "d.ply");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 9);
  }
  EXPECT_THROW(parse_ply_points("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
                                "end_header\n1\n",
                                "e.ply"),
               ParseError);
}

// An element with records and no properties takes no bytes a record: read, it would append
// empty vertices without end. Two elements of one name would be read as one.
TEST(PlyReader, ElementsWithoutPropertiesOrDeclaredTwiceAreRejected) {
  const std::string no_properties =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\n"
      "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  try {
    parse_ply_mesh(no_properties, "p.ply");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 4);
    EXPECT_NE(std::string(e.what()).find("no 'property'"), std::string::npos) << e.what();
  }
  const std::string twice =
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nelement vertex 1\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n1 2 3\n4 5 6\n";
  try {
    parse_ply_points(twice, "t.ply");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(std::string(e.what()).find("declared twice"), std::string::npos) << e.what();
  }
  // An empty element (no records) needs no properties.
  EXPECT_EQ(parse_ply_points("ply\nformat ascii 1.0\nelement camera 0\nelement vertex 1\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "end_header\n1 2 3\n",
                             "c.ply")
                .points.size(),
            1u);
}

TEST(XyzReader, SpacesCommasCommentsAndHeader) {
  const PointSet a = parse_xyz_points("# scan\n1 2 3 0.5\n\n4\t5\t6\n", "a.xyz");
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[1], Eigen::Vector3d(4, 5, 6));
  const PointSet b = parse_xyz_points("intensity,X,Y,Z\n9,1,2,3\n9,4,5,6\n", "b.csv");
  ASSERT_EQ(b.points.size(), 2u);
  EXPECT_EQ(b.points[0], Eigen::Vector3d(1, 2, 3));
  try {
    parse_xyz_points("1 2 3\n4 5\n", "c.xyz");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
  }
}

// A spreadsheet's UTF-8 byte-order mark is not a header: the first point stays. A first line in
// Latin-1 (no-break spaces as separators) is not a header either: an error at line 1.
TEST(XyzReader, ByteOrderMarkAndLatinOneKeepTheFirstPoint) {
  const PointSet a = parse_xyz_points(
      "\xEF\xBB\xBF"
      "1 2 3\n4 5 6\n",
      "a.xyz");
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[0], Eigen::Vector3d(1, 2, 3));
  const PointSet b = parse_xyz_points(
      "\xEF\xBB\xBF"
      "x,y,z\n1,2,3\n",
      "b.csv");
  ASSERT_EQ(b.points.size(), 1u);
  try {
    parse_xyz_points(
        "1\xA0"
        "2\xA0"
        "3\n4 5 6\n",
        "c.xyz");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_EQ(e.file(), "c.xyz");
  }
  EXPECT_THROW(parse_xyz_points(std::string("\xFF\xFE"
                                            "1\0 \0"
                                            "2\0",
                                            8),
                                "d.xyz"),
               ParseError);
}

TEST(PcdReader, AsciiAndBinary) {
  const std::string head =
      "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
      "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n";
  const PointSet a = parse_pcd_points(head + "DATA ascii\n1 2 3 0\n4 5 6 0\n", "a.pcd");
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.points[1], Eigen::Vector3d(4, 5, 6));
  std::string bin = head + "DATA binary\n";
  for (float v : {1.f, 2.f, 3.f}) append(bin, v);
  append<std::uint32_t>(bin, 0);
  for (float v : {-1.f, -2.f, -3.f}) append(bin, v);
  append<std::uint32_t>(bin, 0);
  const PointSet b = parse_pcd_points(bin, "b.pcd");
  ASSERT_EQ(b.points.size(), 2u);
  EXPECT_EQ(b.points[1], Eigen::Vector3d(-1, -2, -3));
  EXPECT_THROW(parse_pcd_points(head + "DATA binary_compressed\n", "c.pcd"), ParseError);
  EXPECT_THROW(parse_pcd_points(head + "DATA ascii\n1 2 3 0\n", "d.pcd"), ParseError);
  // Header counts beyond any file, or sizes PCD does not have, are refused; a huge POINTS with
  // little data ends where the data does, without reserving for it.
  auto with = [&](const std::string& from, const std::string& to) {
    std::string h = head;
    h.replace(h.find(from), from.size(), to);
    return h;
  };
  EXPECT_THROW(parse_pcd_points(with("COUNT 1 1 1 1", "COUNT 1 1 1e66 1") + "DATA ascii\n", "e"),
               ParseError);
  EXPECT_THROW(parse_pcd_points(with("SIZE 4 4 4 4", "SIZE 4 4 4 3") + "DATA ascii\n", "f"),
               ParseError);
  EXPECT_THROW(parse_pcd_points(with("COUNT 1 1 1 1", "COUNT 0 1 1 1") + "DATA ascii\n", "g"),
               ParseError);
  EXPECT_THROW(parse_pcd_points(with("POINTS 2", "POINTS 999999999999") + "DATA binary\n", "h"),
               ParseError);
  EXPECT_THROW(
      parse_pcd_points(with("POINTS 2", "POINTS 999999999999") + "DATA ascii\n1 2 3 0\n", "i"),
      ParseError);
}

TEST(ObjReader, GroupsFacesAndNegativeIndices) {
  const GroupedMesh m = parse_obj_mesh(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\ng trunk_level0\nf 1//1 2//1 3//1\n"
      "g branch_level1\nv 0 0 1\nf -4/1 -3/1 -1/1\n",
      "t.obj");
  ASSERT_EQ(m.vertices.size(), 4u);
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(m.group_names[m.face_group[0]], "trunk_level0");
  EXPECT_EQ(m.group_names[m.face_group[1]], "branch_level1");
  EXPECT_EQ(m.faces[1], (std::vector<std::uint32_t>{0, 1, 3}));
  try {
    parse_obj_mesh("v 0 0 0\nv 1 0 0\nf 1 2 3\n", "u.obj");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
  }
}

// Written .ply keeps millimetres at projected coordinates (doubles there), floats near zero.
TEST(PointSetFile, PlyWrittenAtProjectedCoordinatesKeepsMillimetres) {
  const std::string far = temp_file("far.ply", "");
  const std::string near = temp_file("near.ply", "");
  PointSet ps;
  ps.points = {{500000.001, 5800000.002, 300.003}, {500000.004, 5800000.005, 300.006}};
  write_point_set(ps, far);
  write_point_set({{{0.001, 0.002, 0.003}}}, near);
  const PointSet back = read_point_set(far);
  ASSERT_EQ(back.points.size(), 2u);
  EXPECT_EQ(back.points[1], ps.points[1]);
  EXPECT_NE(read_text_file(far).find("property double x"), std::string::npos);
  EXPECT_NE(read_text_file(near).find("property float x"), std::string::npos);
  std::filesystem::remove(far);
  std::filesystem::remove(near);
}

TEST(PointSetFile, ChoosesTheReaderByExtension) {
  const std::string xyz = temp_file("p.xyz", "1 2 3\n");
  EXPECT_EQ(read_point_set(xyz).points.at(0), Eigen::Vector3d(1, 2, 3));
  const std::string obj = temp_file("p.obj", "v 4 5 6\n");
  EXPECT_EQ(read_point_set(obj).points.at(0), Eigen::Vector3d(4, 5, 6));
  EXPECT_THROW(read_point_set(temp_file("p.e57", "")), ValueError);
  EXPECT_THROW(read_point_set("/nonexistent/fspm_scan.ply"), IoError);
  std::filesystem::remove(xyz);
  std::filesystem::remove(obj);
}

TEST(PlyReader, ReadsFacesAsAMesh) {
  // A quad and a triangle after a non-list property; ASCII and binary little endian.
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty uchar flags\n"
      "property list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n7 4 0 1 2 3\n7 3 0 1 4\n";
  GroupedMesh m = parse_ply_mesh(ascii, "q.ply");
  ASSERT_EQ(m.vertices.size(), 5u);
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(m.faces[0], (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(m.faces[1], (std::vector<std::uint32_t>{0, 1, 4}));
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
      "property double y\nproperty double z\nelement face 1\n"
      "property list uchar uint vertex_index\nend_header\n";
  const double xyz[9] = {0, 0, 0, 2, 0, 0, 0, 3, 0};
  binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const unsigned char count = 3;
  const std::uint32_t idx[3] = {2, 0, 1};
  binary.append(reinterpret_cast<const char*>(&count), 1);
  binary.append(reinterpret_cast<const char*>(idx), sizeof idx);
  m = parse_ply_mesh(binary, "b.ply");
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.faces[0], (std::vector<std::uint32_t>{2, 0, 1}));
  EXPECT_EQ(m.vertices[2], Eigen::Vector3d(0, 3, 0));
  // A face naming a sixth vertex of five.
  std::string bad = ascii;
  bad.replace(bad.find("7 3 0 1 4"), 9, "7 3 0 1 5");
  EXPECT_THROW(parse_ply_mesh(bad, "bad.ply"), ParseError);
}

// Little endian takes the bulk path of the common layouts, big endian the value-by-value one:
// both give the hand-written mesh (mixed scalar types, properties around x and around the face
// list, 4- and 3-gons).
TEST(PlyReader, BulkAndValueByValueReadingAgree) {
  const auto file = [](bool big, std::int32_t last_index, std::size_t drop_bytes) {
    std::string data = std::string("ply\nformat ") +
                       (big ? "binary_big_endian" : "binary_little_endian") +
                       " 1.0\nelement vertex 5\nproperty uchar red\nproperty float x\n"
                       "property double y\nproperty int16 z\nelement face 2\n"
                       "property uchar flags\nproperty list uchar int vertex_indices\n"
                       "property int16 material\nend_header\n";
    const double corners[5][3] = {{0, 0, 0}, {1.5, 0, 0}, {1.5, 2.25, 0}, {0, 2.25, 0}, {0, 0, 7}};
    for (const auto& c : corners) {
      append<std::uint8_t>(data, 9);
      append(data, static_cast<float>(c[0]), big);
      append(data, c[1], big);
      append(data, static_cast<std::int16_t>(c[2]), big);
    }
    append<std::uint8_t>(data, 1);
    append<std::uint8_t>(data, 4);
    for (std::int32_t i : {0, 1, 2, 3}) append(data, i, big);
    append<std::int16_t>(data, 5, big);
    append<std::uint8_t>(data, 1);
    append<std::uint8_t>(data, 3);
    for (std::int32_t i : {0, 1, last_index}) append(data, i, big);
    append<std::int16_t>(data, 5, big);
    data.resize(data.size() - drop_bytes);
    return data;
  };
  for (bool big : {false, true}) {
    const GroupedMesh m = parse_ply_mesh(file(big, 4, 0), "m.ply");
    ASSERT_EQ(m.vertices.size(), 5u) << big;
    EXPECT_EQ(m.vertices[2], Eigen::Vector3d(1.5, 2.25, 0)) << big;
    EXPECT_EQ(m.vertices[4], Eigen::Vector3d(0, 0, 7)) << big;
    ASSERT_EQ(m.faces.size(), 2u) << big;
    EXPECT_EQ(m.faces[0], (std::vector<std::uint32_t>{0, 1, 2, 3})) << big;
    EXPECT_EQ(m.faces[1], (std::vector<std::uint32_t>{0, 1, 4})) << big;
    EXPECT_EQ(parse_ply_points(file(big, 4, 0), "m.ply").points.size(), 5u) << big;
    EXPECT_THROW(parse_ply_mesh(file(big, -1, 0), "n.ply"), ParseError) << big;
    // The last index cut in half: the error names the byte where the file ends.
    const std::string cut = file(big, 4, 4);
    try {
      parse_ply_mesh(cut, "t.ply");
      ADD_FAILURE() << "expected a ParseError";
    } catch (const ParseError& e) {
      EXPECT_NE(e.message().find("byte " + std::to_string(cut.size() - 2)), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace fspm::scans
