// fspm crown with its default options, through the command line: a disc mask whose --height-m is
// its diameter inflates to the sphere of that diameter (Argudo 4.3.2, Fig. 4.13). The reference
// is the disc the mask holds, in closed form: pixels whose centres lie within R of (127.5, 127.5)
// span rows 28 to 227, 2R pixels, and cover pi R^2 to 1e-4; at --height-m 2R s the sphere has
// radius R s, its centre on the photograph's axis, R s above the crown's lowest point.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

constexpr int kSize = 256;
constexpr double kRadiusPx = 100.0;
constexpr double kCentrePx = 127.5;

void write_disc_mask(const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << kSize << ' ' << kSize << "\n255\n";
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const double dx = x - kCentrePx, dy = y - kCentrePx;
      out.put(static_cast<char>(dx * dx + dy * dy <= kRadiusPx * kRadiusPx ? 255 : 0));
    }
  }
}

// A photograph of foliage: green speckle of random brightness (seeded), so the relief of
// Argudo 4.4 and the synthesized back have texture to work on; `speckle` 0 gives one colour.
void write_foliage_photo(const std::filesystem::path& path, double speckle) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << kSize << ' ' << kSize << "\n255\n";
  for (int i = 0; i < kSize * kSize; ++i) {
    const double v = 0.5 + speckle * (u(rng) - 0.5);
    for (const double base : {60.0, 140.0, 45.0}) {
      out.put(static_cast<char>(static_cast<int>(base * (0.4 + 1.2 * v))));
    }
  }
}

struct Mesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

// A binary little-endian PLY as fspm writes it (float vertex properties, then faces as a uchar
// count, uint indices and uchar properties after them), read from its header alone.
Mesh read_ply(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line, element;
  std::size_t vertices = 0, faces = 0, vertex_floats = 0, face_extra = 0;
  while (std::getline(in, line) && line != "end_header") {
    std::istringstream words(line);
    std::string word, type;
    words >> word;
    if (word == "element") words >> element >> (element == "vertex" ? vertices : faces);
    if (word == "property" && element == "vertex") ++vertex_floats;
    if (word == "property" && element == "face" && line.find("list") == std::string::npos) {
      ++face_extra;
    }
  }
  Mesh m;
  std::vector<float> v(vertex_floats);
  for (std::size_t i = 0; i < vertices; ++i) {
    in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(4 * vertex_floats));
    m.vertices.emplace_back(v[0], v[1], v[2]);
  }
  for (std::size_t i = 0; i < faces; ++i) {
    unsigned char count = 0;
    in.read(reinterpret_cast<char*>(&count), 1);
    std::array<std::uint32_t, 3> t{};
    in.read(reinterpret_cast<char*>(t.data()), 12);
    in.ignore(static_cast<std::streamsize>(face_extra));
    if (count == 3) m.triangles.push_back(t);
  }
  return m;
}

// Enclosed volume by the divergence theorem: the sum of the signed tetrahedra from the origin.
double volume(const Mesh& m) {
  double sum = 0.0;
  for (const auto& t : m.triangles) {
    sum += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
  }
  return std::abs(sum);
}

void expect_sphere(double speckle) {
  const auto dir = scratch_dir("crown_sphere");
  write_disc_mask(dir / "disc.pgm");
  write_foliage_photo(dir / "photo.ppm", speckle);
  const double height_m = 6.0, r_m = height_m / 2.0;
  const auto r =
      run_fspm("crown " + (dir / "photo.ppm").string() + " --mask " + (dir / "disc.pgm").string() +
               " --height-m 6 -o " + (dir / "crown.ply").string() + " --json");
  if (r.err.find("without OpenImageIO") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Mesh mesh = read_ply(dir / "crown.ply");
  ASSERT_GT(mesh.triangles.size(), 10000u);
  const double sphere = 4.0 / 3.0 * M_PI * r_m * r_m * r_m;
  const double v = volume(mesh);
  double radius_sum = 0.0;
  for (const auto& p : mesh.vertices) radius_sum += (p - Eigen::Vector3d(0, 0, r_m)).norm();
  const double mean_radius = radius_sum / static_cast<double>(mesh.vertices.size());
  std::cout << "speckle " << speckle << ": volume " << v / sphere
            << " of the sphere's, mean radius " << mean_radius / r_m << " of its radius\n";
  EXPECT_NEAR(v / sphere, 1.0, 0.03);
  EXPECT_NEAR(mean_radius / r_m, 1.0, 0.015);
  // The command's own figure agrees with the mesh it wrote.
  EXPECT_NEAR(nlohmann::json::parse(r.out)["volume_m3"].get<double>(), v, 1e-3 * v);
}

TEST(CrownCli, DiscMaskOfItsDiameterIsASphereByDefault) { expect_sphere(0.0); }

TEST(CrownCli, DiscMaskUnderFoliageTextureIsASphereByDefault) { expect_sphere(0.8); }

}  // namespace
}  // namespace fspm
