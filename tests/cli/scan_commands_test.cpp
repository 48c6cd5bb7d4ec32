// fspm scan, fspm encode and fspm tree convert of a grouped OBJ or glTF, run as a user would.
#include <gtest/gtest.h>
#include <spdlog/fmt/fmt.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/scans/gltf_test_file.hpp"

namespace fspm {
namespace {

using testing::read_text;
using testing::run_fspm;
using testing::scratch_dir;

const std::string kTree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";

TEST(ScanCli, ScanThenEncodeReportsWhatItWrote) {
  const auto dir = scratch_dir("scan_encode");
  const std::string scan = (dir / "scan.ply").string();
  auto r = run_fspm("scan " + kTree + " -o " + scan + " --seed 3 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = nlohmann::json::parse(r.out);
  ASSERT_GT(s["points"].get<std::size_t>(), 1000u);
  const std::string model = (dir / "tree.clusters").string();
  r = run_fspm("encode " + scan + " --species pine --fs 0.9 -o " + model + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], s["points"]);
  EXPECT_EQ(j["bytes"].get<std::uintmax_t>(), std::filesystem::file_size(model));
  EXPECT_GE(j["skeleton_nodes"].get<int>(), 1);
  EXPECT_DOUBLE_EQ(j["beta"].get<double>(), 1.3);  // pine, Pirk Table 3.1
  EXPECT_DOUBLE_EQ(j["f_s"].get<double>(), 0.9);   // overridden
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  // The example tree forks 0.15 m above the ground into one limb that is 0.056 m thick at 1.3 m
  // (the thickest internode there in the tree file) and branches of 1-2 cm: no codominant
  // stems, the dbh is the limb's (within 10 %: it is eight scanner steps across).
  ASSERT_TRUE(j["dbh_m"].is_number()) << r.err;
  EXPECT_NEAR(j["dbh_m"].get<double>(), 0.056, 0.0056);
  EXPECT_TRUE(j["breast_height_stems_m"].empty());
}

// A cloud without a diameter at breast height (the airborne example: a handful of stem points)
// gets the fitted root diameter of eq. 3.1 flagged, on stderr and in the JSON.
TEST(ScanCli, EncodeFlagsAnUnconfirmedRootDiameter) {
  const auto dir = scratch_dir("scan_encode_airborne");
  const auto r = run_fspm("encode " + std::string(FSPM_SOURCE_DIR) +
                          "/examples/scans/ahn4_tree_121913_487434.las -o " +
                          (dir / "tree.clusters").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["dbh_m"].is_null());
  const std::string warnings = j["warnings"].dump();
  EXPECT_NE(warnings.find("give --root-diameter"), std::string::npos) << warnings;
  EXPECT_NE(r.err.find("[warning]"), std::string::npos) << r.err;
}

// An MTG is a tree model like the others: scanned as the same tree in .treeb gives the same
// points.
TEST(ScanCli, EncodeAndScanReadMtgTrees) {
  const auto dir = scratch_dir("scan_mtg");
  const std::string mtg = (dir / "tree.mtg").string();
  const std::string treeb = (dir / "tree.treeb").string();
  ASSERT_EQ(run_fspm("tree convert " + kTree + " " + mtg).exit_code, 0);
  ASSERT_EQ(run_fspm("tree convert " + mtg + " " + treeb).exit_code, 0);
  const auto from_treeb = run_fspm("scan " + treeb + " --seed 3 -o " + (dir / "a.ply").string());
  const auto from_mtg = run_fspm("scan " + mtg + " --seed 3 -o " + (dir / "b.ply").string());
  ASSERT_EQ(from_treeb.exit_code, 0) << from_treeb.err;
  ASSERT_EQ(from_mtg.exit_code, 0) << from_mtg.err;
  EXPECT_GT(read_text(dir / "a.ply").size(), 10000u);
  EXPECT_EQ(read_text(dir / "a.ply"), read_text(dir / "b.ply"));
  const auto r = run_fspm("encode " + mtg + " -o " + (dir / "t.clusters").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out)["points"].get<std::size_t>(), 1000u);
  std::filesystem::remove_all(dir);
}

TEST(ScanCli, MistakesExitWithOneLine) {
  const auto dir = scratch_dir("scan_bad");
  const std::string xyz = (dir / "p.xyz").string();
  std::ofstream(xyz) << "0 0 0\n0 0 1\n0 0 x\n";
  auto r = run_fspm("encode " + xyz + " -o " + (dir / "m.clusters").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(":3"), std::string::npos) << r.err;  // the line
  r = run_fspm("encode " + kTree + " --species pinus -o " + (dir / "n.clusters").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("pine"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "n.clusters"));
}

TEST(ScanCli, TreeConvertReadsAGroupedObj) {
  const auto dir = scratch_dir("scan_obj");
  const std::string obj = (dir / "branches.obj").string();
  std::ofstream out(obj);
  int v = 1;
  const auto square = [&](double x, double y, double z, double w) {
    for (const auto& [dx, dy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      out << "v " << x + dx * w / 2 << ' ' << y + dy * w / 2 << ' ' << z << '\n';
    }
    out << "f " << v << ' ' << v + 1 << ' ' << v + 2 << ' ' << v + 3 << '\n';
    v += 4;
  };
  out << "g trunk1\n";
  for (int k = 0; k < 4; ++k) square(0, 0, k, 0.3);
  out << "g branch1\n";
  for (int k = 1; k <= 2; ++k) square(0.4 * k, 0, 1.1 + 0.3 * k, 0.1);
  out.close();
  const std::string tree = (dir / "tree.tree").string();
  const auto r = run_fspm("tree convert " + obj + " " + tree);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TreeGraph t = read_tree_file(tree);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t.parent(3), 0u);  // the branch hangs at the trunk point z = 1
  EXPECT_NEAR(t.radius(4), 0.05, 1e-9);
}

// A mesh as input of encode: its vertices are the points (fspm mesh's own count of what it wrote).
TEST(ScanCli, EncodeReadsTheVerticesOfAGlb) {
  const auto dir = scratch_dir("scan_glb");
  const std::string mesh = (dir / "tree.glb").string();
  auto r = run_fspm("mesh " + kTree + " -o " + mesh + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto written = nlohmann::json::parse(r.out);
  r = run_fspm("encode " + mesh + " -o " + (dir / "tree.clusters").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], written["vertices"]);
  EXPECT_GE(j["skeleton_nodes"].get<int>(), 1);
}

// The branches of TreeConvertReadsAGroupedObj as glTF nodes, each square split into two
// triangles: the same skeleton.
TEST(ScanCli, TreeConvertReadsAGroupedGlb) {
  const auto dir = scratch_dir("scan_glb_groups");
  std::vector<scans::test::GltfPart> parts{{"trunk1", "a", {}, {}}, {"branch1", "b", {}, {}}};
  const auto square = [](scans::test::GltfPart& p, float x, float y, float z, float w) {
    const auto first = static_cast<std::uint32_t>(p.positions.size() / 3);
    for (const auto& [dx, dy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      p.positions.insert(p.positions.end(), {x + dx * w / 2, y + dy * w / 2, z});
    }
    p.indices.insert(p.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  };
  for (int k = 0; k < 4; ++k) square(parts[0], 0, 0, static_cast<float>(k), 0.25f);
  for (int k = 1; k <= 2; ++k) square(parts[1], 0.5f * k, 0, 1.25f + 0.25f * k, 0.125f);
  const std::string glb = (dir / "branches.glb").string();
  scans::test::write_glb(glb, parts);
  const std::string tree = (dir / "tree.tree").string();
  const auto r = run_fspm("tree convert " + glb + " " + tree);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TreeGraph t = read_tree_file(tree);
  ASSERT_EQ(t.size(), 5u);
  EXPECT_EQ(t.parent(3), 0u);  // the branch hangs at the trunk point z = 1
  EXPECT_NEAR(t.radius(0), 0.125, 1e-6);
  EXPECT_NEAR(t.radius(4), 0.0625, 1e-6);
}

// A vertical cylinder of radius 0.15 m and height 3 m (a bare trunk) as a LAS 1.2 file of point
// format 0 (ASPRS LAS 1.4 R15, table 3), millimetre scale, at projected coordinates.
std::string cylinder_las() {
  std::string s(227, '\0');
  const auto put = [&s](std::size_t at, auto v) { std::memcpy(s.data() + at, &v, sizeof v); };
  std::memcpy(s.data(), "LASF", 4);
  put(24, std::uint8_t{1});
  put(25, std::uint8_t{2});
  put(94, std::uint16_t{227});
  put(96, std::uint32_t{227});
  put(105, std::uint16_t{20});
  const double offset[3] = {500000.0, 5800000.0, 300.0};
  for (int c = 0; c < 3; ++c) {
    put(131 + 8 * static_cast<std::size_t>(c), 0.001);
    put(155 + 8 * static_cast<std::size_t>(c), offset[c]);
  }
  std::uint32_t n = 0;
  for (int ring = 0; ring < 150; ++ring) {
    for (int k = 0; k < 48; ++k, ++n) {
      const double a = 2.0 * std::numbers::pi * (k + 0.5 * (ring % 2)) / 48.0;
      const std::int32_t xyz[3] = {static_cast<std::int32_t>(std::lround(150.0 * std::cos(a))),
                                   static_cast<std::int32_t>(std::lround(150.0 * std::sin(a))),
                                   20 * ring};
      s.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
      s.append(8, '\0');
    }
  }
  put(107, n);
  return s;
}

// A LAS trunk at projected coordinates: measured as at the origin, outputs in its coordinates.
TEST(ScanCli, EncodeMeasuresALasTrunkAtProjectedCoordinates) {
  const auto dir = scratch_dir("scan_las");
  const std::string las = (dir / "trunk.las").string();
  std::ofstream(las, std::ios::binary) << cylinder_las();
  const std::string csv = (dir / "cylinders.csv").string();
  const auto r = run_fspm("encode " + las + " -o " + (dir / "t.clusters").string() +
                          " --cylinders " + csv + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], 7200);
  EXPECT_NEAR(j["dbh_m"].get<double>(), 0.30, 0.30 * 0.03);
  EXPECT_NEAR(j["height_m"].get<double>(), 2.98, 0.02 * 2.98);
  EXPECT_NEAR(j["woody_volume_m3"].get<double>(), std::numbers::pi * 0.15 * 0.15 * 2.98,
              0.15 * std::numbers::pi * 0.15 * 0.15 * 2.98);
  EXPECT_EQ(j["origin"][1], 5799999.0);
  EXPECT_TRUE(j["warnings"].empty()) << j["warnings"];
  const std::string text = read_text(csv);
  EXPECT_EQ(text.rfind("start_x,start_y,start_z,axis_x,axis_y,axis_z,length,radius,parent,", 0),
            0u);
  // One row per cylinder; the first starts at the trunk's foot, in the file's coordinates.
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')),
            j["cylinders"].get<std::size_t>() + 1);
  const std::string first = text.substr(text.find('\n') + 1);
  EXPECT_NEAR(std::stod(first), 500000.0, 0.2);
  std::filesystem::remove_all(dir);
}

// No tree: the walls of a house exit 1 with the warning and write nothing; .laz is refused.
// The bounding box a LAS 1.2 header records (max x, min x, max y, min y, max z, min z as
// doubles at byte 179), written by the scan's producer.
std::array<double, 6> las_header_bounds(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 227> header{};
  in.read(header.data(), header.size());
  std::array<double, 6> b{};
  std::memcpy(b.data(), header.data() + 179, sizeof(b));
  return b;
}

// Real airborne clouds (AHN4, examples/scans) at projected coordinates: their height is the
// header's z range, they have no stem points at breast height (no DBH, a warning, exit 0), and
// the branch skeleton spans the crown the header bounds.
TEST(ScanCli, AirborneCloudsOfStreetTreesAreMeasuredWithoutADbh) {
  const auto dir = scratch_dir("ahn4");
  for (const char* name : {"ahn4_tree_121913_487434", "ahn4_tree_121922_487459"}) {
    SCOPED_TRACE(name);
    const std::string las = std::string(FSPM_SOURCE_DIR) + "/examples/scans/" + name + ".las";
    const auto b = las_header_bounds(las);  // max x, min x, max y, min y, max z, min z
    const std::string branches = (dir / (std::string(name) + ".tree")).string();
    const auto r = run_fspm("encode " + las + " -o " + (dir / "t.clusters").string() +
                            " --branch-skeleton " + branches + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NEAR(j["height_m"].get<double>(), b[4] - b[5], 0.01);
    EXPECT_TRUE(j["dbh_m"].is_null());
    EXPECT_NE(r.err.find("trunk points 1.2-1.4 m above the lowest point"), std::string::npos)
        << r.err;
    EXPECT_NEAR(j["origin"][0].get<double>(), std::floor(b[1]), 1.0);
    EXPECT_NEAR(j["origin"][1].get<double>(), std::floor(b[3]), 1.0);
    const TreeGraph t = read_tree_file(branches);
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (NodeId n = 0; n < t.size(); ++n) {
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min({lo[k], t.start(n)[k], t.end(n)[k]});
        hi[k] = std::max({hi[k], t.start(n)[k], t.end(n)[k]});
      }
    }
    const double want_lo[3] = {b[1], b[3], b[5]}, want_hi[3] = {b[0], b[2], b[4]};
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(lo[k], want_lo[k], 0.7) << k;
      EXPECT_NEAR(hi[k], want_hi[k], 0.7) << k;
    }
  }
}

// The bounds of a tree file's segments: lo[3], hi[3].
std::array<std::array<double, 3>, 2> tree_bounds(const TreeGraph& t) {
  std::array<std::array<double, 3>, 2> b{{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}}};
  for (NodeId n = 0; n < t.size(); ++n) {
    for (int k = 0; k < 3; ++k) {
      b[0][k] = std::min({b[0][k], t.start(n)[k], t.end(n)[k]});
      b[1][k] = std::max({b[1][k], t.start(n)[k], t.end(n)[k]});
    }
  }
  return b;
}

// The default main skeleton (--skeleton) of a real cloud follows the trunk and the limbs into the
// crown: its top reaches 90 % of the cloud's height and it spans 85 % of the crown's width along x
// and y, all from the LAS header's bounds. Pirk's split (--pirk-split) stops lower.
TEST(ScanCli, DefaultSkeletonOfARealCloudReachesTheTopAndSpansTheCrown) {
  const auto dir = scratch_dir("ahn4_main");
  for (const char* name : {"ahn4_tree_121913_487434", "ahn4_tree_121922_487459"}) {
    SCOPED_TRACE(name);
    const std::string las = std::string(FSPM_SOURCE_DIR) + "/examples/scans/" + name + ".las";
    const auto h = las_header_bounds(las);  // max x, min x, max y, min y, max z, min z
    const std::string main = (dir / "main.tree").string();
    const std::string pirk = (dir / "pirk.tree").string();
    auto r =
        run_fspm("encode " + las + " -o " + (dir / "t.clusters").string() + " --skeleton " + main);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_fspm("encode " + las + " -o " + (dir / "p.clusters").string() + " --pirk-split" +
                 " --skeleton " + pirk);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto b = tree_bounds(read_tree_file(main));
    EXPECT_GE(b[1][2] - h[5], 0.9 * (h[4] - h[5]));
    EXPECT_GE(b[1][0] - b[0][0], 0.85 * (h[0] - h[1]));
    EXPECT_GE(b[1][1] - b[0][1], 0.85 * (h[2] - h[3]));
    EXPECT_LT(tree_bounds(read_tree_file(pirk))[1][2] - h[5], 0.9 * (h[4] - h[5]));
  }
}

// The reach rule (--main-branch-reach, default 0.1) keeps limbs the share rule alone leaves in
// clusters: more main nodes, fewer points in clusters; values outside [0, 1] are refused.
TEST(ScanCli, MainBranchReachKeepsMoreLimbs) {
  const auto dir = scratch_dir("ahn4_reach");
  const std::string las =
      std::string(FSPM_SOURCE_DIR) + "/examples/scans/ahn4_tree_121913_487434.las";
  const std::string with = (dir / "with.tree").string(), without = (dir / "without.tree").string();
  auto r =
      run_fspm("encode " + las + " -o " + (dir / "a.clusters").string() + " --skeleton " + with);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("encode " + las + " -o " + (dir / "b.clusters").string() +
               " --main-branch-reach 0 --skeleton " + without);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(read_tree_file(with).size(), read_tree_file(without).size() * 3 / 2);
  r = run_fspm("encode " + las + " -o " + (dir / "c.clusters").string() + " --main-branch-reach 2");
  EXPECT_EQ(r.exit_code, 1);
}

// Points on the cylinder of radius r around a -> b every step_m, without the stretch between the
// shares gap_from and gap_to of its length, moved by `offset`, written to `out` in full precision.
void write_cylinder(std::ofstream& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    double r, double step_m, const Eigen::Vector3d& offset, double gap_from = 2.0,
                    double gap_to = 2.0) {
  const Eigen::Vector3d axis = (b - a).normalized();
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  const double length = (b - a).norm();
  const int around = std::max(6, static_cast<int>(2.0 * std::numbers::pi * r / step_m));
  for (double s = 0.0; s <= length; s += step_m) {
    if (s / length > gap_from && s / length < gap_to) continue;
    for (int k = 0; k < around; ++k) {
      const double t = 2.0 * std::numbers::pi * k / around;
      const Eigen::Vector3d p = offset + a + s * axis + r * (std::cos(t) * u + std::sin(t) * v);
      out << fmt::format("{:.4f} {:.4f} {:.4f}\n", p.x(), p.y(), p.z());
    }
  }
}

// A branch with a 0.6 m occlusion gap, at projected coordinates: the warning says how many gaps
// were bridged and where, in the input's coordinates (the offset added back), and --json lists
// the bridge's ends.
TEST(ScanCli, BridgedGapsAreReportedWhereTheyAre) {
  const auto dir = scratch_dir("scan_gaps");
  const std::string xyz = (dir / "gap.xyz").string();
  const Eigen::Vector3d offset(500000.0, 5800000.0, 300.0);
  const Eigen::Vector3d a0(0, 0, 2), dir45 = Eigen::Vector3d(1, 0, 1).normalized();
  {
    std::ofstream out(xyz);
    write_cylinder(out, {0, 0, 0}, {0, 0, 4}, 0.1, 0.02, offset);
    write_cylinder(out, a0, a0 + 2.83 * dir45, 0.03, 0.01, offset, 1.0 / 2.83, 1.6 / 2.83);
  }
  const auto r = run_fspm("encode " + xyz + " --root-diameter 0.2 -o " +
                          (dir / "gap.clusters").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["gaps"].size(), 1u);
  const Eigen::Vector3d near_end = offset + a0 + 1.0 * dir45, far_end = offset + a0 + 1.6 * dir45;
  const auto at = [&](const char* key) {
    const auto& p = j["gaps"][0][key];
    return Eigen::Vector3d(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  };
  EXPECT_LT((at("from") - far_end).norm(), 0.08);
  EXPECT_LT((at("to") - near_end).norm(), 0.08);
  const Eigen::Vector3d mid = 0.5 * (near_end + far_end);
  EXPECT_NE(r.err.find("1 occlusion gap "), std::string::npos) << r.err;
  const std::size_t at_pos = r.err.find(" at (");
  ASSERT_NE(at_pos, std::string::npos) << r.err;
  Eigen::Vector3d said;
  ASSERT_EQ(
      std::sscanf(r.err.c_str() + at_pos, " at (%lf, %lf, %lf)", &said.x(), &said.y(), &said.z()),
      3)
      << r.err;
  EXPECT_LT((said - mid).norm(), 0.08) << r.err;
  const auto& warnings = j["warnings"];
  EXPECT_TRUE(std::any_of(warnings.begin(), warnings.end(), [](const auto& w) {
    return w.template get<std::string>().find("occlusion gap") != std::string::npos;
  }));
}

TEST(ScanCli, AHouseIsNoTreeAndLazIsRefused) {
  const auto dir = scratch_dir("scan_house");
  const std::string xyz = (dir / "house.xyz").string();
  {
    std::ofstream out(xyz);
    for (int z = 0; z <= 60; ++z) {
      for (int s = 0; s < 160; ++s) {
        out << s * 0.05 << " 0 " << z * 0.05 << "\n" << s * 0.05 << " 6 " << z * 0.05 << "\n";
        if (s < 120) out << "0 " << s * 0.05 << " " << z * 0.05 << "\n";
        if (s < 120) out << "8 " << s * 0.05 << " " << z * 0.05 << "\n";
      }
    }
  }
  const std::string model = (dir / "house.clusters").string();
  auto r = run_fspm("encode " + xyz + " --root-diameter 0.3 -o " + model + " --json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no vertical trunk found"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(model));
  EXPECT_FALSE(nlohmann::json::parse(r.out)["warnings"].empty());
  const std::string laz = (dir / "tree.laz").string();
  std::ofstream(laz, std::ios::binary) << cylinder_las();
  r = run_fspm("encode " + laz + " -o " + model);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("laszip"), std::string::npos) << r.err;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fspm
