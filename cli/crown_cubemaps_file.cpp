#include "cli/crown_cubemaps_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "crown/billboard_cloud.hpp"
#include "crown/cubemap.hpp"
#include "crown/image_io.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/json_fields.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;
constexpr const char* kFormatKey = "fspm_crown_cubemaps";
constexpr std::uint64_t kBillboardSeed = 1;

// A cubemap strip (6N x N) of `channels` channels, or ValueError naming the file.
crown::Raster read_strip(const std::string& path, int size, int channels) {
  crown::Raster r = crown::read_raster(path);
  if (r.width != 6 * size || r.height != size || r.channels < channels) {
    throw ValueError("expected a cubemap strip of 6 x " + std::to_string(size) + " by " +
                         std::to_string(size) + " pixels, got " + std::to_string(r.width) + " x " +
                         std::to_string(r.height),
                     path);
  }
  return r;
}

struct Description {
  Eigen::Vector3f centre_m = Eigen::Vector3f::Zero();
  int size = 0;
  std::string color, radius;  // resolved against the description's directory
};

Description read_description(const std::string& path) {
  // Through the one JSON reader: a key given twice is refused, not taken at its last value.
  const nlohmann::json j = parse_json_text(read_text_input_file(path), path);
  const char* expected =
      "a crown cubemaps description (fspm_crown_cubemaps, centre_m, cubemap_size, color_cubemap, "
      "radius_cubemap)";
  try {
    if (j.at(kFormatKey).get<int>() != 1)
      throw ValueError(std::string("expected ") + expected, path);
    Description d;
    const auto c = j.at("centre_m").get<std::vector<float>>();
    if (c.size() != 3) throw ValueError("centre_m: expected [x, y, z]", path);
    d.centre_m = {c[0], c[1], c[2]};
    d.size = j.at("cubemap_size").get<int>();
    if (d.size < 1 || d.size > 8192) throw ValueError("cubemap_size: expected 1 to 8192", path);
    const fs::path dir = fs::path(path).parent_path();
    d.color = (dir / j.at("color_cubemap").get<std::string>()).string();
    d.radius = (dir / j.at("radius_cubemap").get<std::string>()).string();
    return d;
  } catch (const nlohmann::json::exception&) {
    throw ValueError(std::string("expected ") + expected, path);
  }
}

}  // namespace

std::string crown_cubemaps_path(const std::string& mesh_path) {
  const fs::path p(mesh_path);
  return (p.parent_path() / (p.stem().string() + "_cubemaps.json")).string();
}

void write_crown_cubemaps(const std::string& path, const Eigen::Vector3f& centre_m, int size,
                          const std::string& color_path, const std::string& radius_path) {
  const nlohmann::json j = {{kFormatKey, 1},
                            {"centre_m", {centre_m.x(), centre_m.y(), centre_m.z()}},
                            {"cubemap_size", size},
                            {"color_cubemap", fs::path(color_path).filename().string()},
                            {"radius_cubemap", fs::path(radius_path).filename().string()}};
  write_file_atomically(path, [&](std::ostream& out) { out << j.dump(2) << '\n'; });
}

graphics::ReliefCrown read_relief_crown(const std::string& mesh_path) {
  const std::string path = crown_cubemaps_path(mesh_path);
  if (!fs::is_regular_file(path)) {
    throw IoError(
        "no crown cubemaps beside the mesh (expected " + path + ", written by fspm crown)",
        mesh_path);
  }
  const Description d = read_description(path);
  const crown::Raster radius = read_strip(d.radius, d.size, 1);
  const crown::Raster color = read_strip(d.color, d.size, 3);
  graphics::ReliefCrown c;
  c.face_size = d.size;
  c.centre_m = d.centre_m;
  const std::size_t texels = static_cast<std::size_t>(6 * d.size) * d.size;
  c.radius_m.resize(texels);
  c.rgb.resize(3 * texels);
  for (std::size_t i = 0; i < texels; ++i) {
    c.radius_m[i] = radius.values[i * radius.channels];
    for (int k = 0; k < 3; ++k) {
      const float v = std::clamp(color.values[i * color.channels + k], 0.0f, 1.0f);
      c.rgb[3 * i + k] = static_cast<std::uint8_t>(std::lround(255.0f * v));
    }
  }
  // Argudo 5.2's billboards for close views, the same for every reading (a fixed seed).
  std::mt19937_64 rng(kBillboardSeed);
  c.billboards_m = crown::billboard_centres(crown::cubemap_from_strip(radius), d.centre_m, rng);
  c.validate();
  return c;
}

}  // namespace fspm::cli
