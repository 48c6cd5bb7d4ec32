// Binary glTF 2.0 (.glb): one mesh with a primitive per material sharing the vertex accessors.
// Attributes are application-specific vertex attributes (glTF 2.0 section 3.7.2.1: names start
// with an underscore), e.g. "age" -> "_AGE"; mesh.extras.fspm_attributes maps them back.
#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "fspm/atomic_file.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF writer assumes little endian");

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;

std::string gltf_attribute_name(const std::string& name) {
  std::string out = "_";
  for (char c : name) {
    out += std::isalnum(static_cast<unsigned char>(c))
               ? static_cast<char>(std::toupper(static_cast<unsigned char>(c)))
               : '_';
  }
  return out;
}

}  // namespace

void write_glb(const TriangleMesh& mesh, const std::string& path) {
  using nlohmann::json;
  const std::size_t nv = mesh.vertex_count();

  // Indices split by material, bark first.
  std::vector<std::uint32_t> indices[2];
  const std::size_t leaf_count = mesh.triangle_count(Material::kLeaf);
  indices[0].reserve(3 * (mesh.triangle_count() - leaf_count));
  indices[1].reserve(3 * leaf_count);
  for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
    const int m = i < mesh.materials.size() && mesh.materials[i] == Material::kLeaf ? 1 : 0;
    indices[m].insert(indices[m].end(), mesh.triangles[i].begin(), mesh.triangles[i].end());
  }

  struct View {
    const void* data;
    std::size_t bytes;
  };
  std::vector<View> views;
  json buffer_views = json::array();
  json accessors = json::array();
  std::size_t bin_size = 0;
  auto add_view = [&](const void* data, std::size_t bytes, int target) {
    buffer_views.push_back(
        {{"buffer", 0}, {"byteOffset", bin_size}, {"byteLength", bytes}, {"target", target}});
    views.push_back({data, bytes});
    bin_size += (bytes + 3) & ~std::size_t{3};
    return buffer_views.size() - 1;
  };
  auto add_accessor = [&](std::size_t view, int component, std::size_t count,
                          const char* type) -> std::size_t {
    accessors.push_back(
        {{"bufferView", view}, {"componentType", component}, {"count", count}, {"type", type}});
    return accessors.size() - 1;
  };

  json attributes = json::object();
  if (nv > 0) {
    const Eigen::Vector3f lo = mesh.bbox_min();
    const Eigen::Vector3f hi = mesh.bbox_max();
    const std::size_t pos =
        add_accessor(add_view(mesh.positions.data(), nv * 12, kArrayBuffer), kFloat, nv, "VEC3");
    accessors[pos]["min"] = {lo.x(), lo.y(), lo.z()};  // required for POSITION
    accessors[pos]["max"] = {hi.x(), hi.y(), hi.z()};
    attributes["POSITION"] = pos;
    attributes["NORMAL"] =
        add_accessor(add_view(mesh.normals.data(), nv * 12, kArrayBuffer), kFloat, nv, "VEC3");
    attributes["TEXCOORD_0"] =
        add_accessor(add_view(mesh.uvs.data(), nv * 8, kArrayBuffer), kFloat, nv, "VEC2");
  }
  json names = json::object();
  for (const auto& a : mesh.attributes) {
    if (nv == 0) break;
    const std::string key = gltf_attribute_name(a.name);
    attributes[key] =
        add_accessor(add_view(a.values.data(), nv * 4, kArrayBuffer), kFloat, nv, "SCALAR");
    names[key] = a.name;
  }

  json primitives = json::array();
  for (int m = 0; m < 2; ++m) {
    if (indices[m].empty()) continue;
    const std::size_t acc =
        add_accessor(add_view(indices[m].data(), indices[m].size() * 4, kElementArrayBuffer),
                     kUnsignedInt, indices[m].size(), "SCALAR");
    primitives.push_back(
        {{"attributes", attributes}, {"indices", acc}, {"material", m}, {"mode", 4}});
  }

  json doc = {
      {"asset", {{"version", "2.0"}, {"generator", "fspm"}}},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", json::array({0})}}})},
      {"materials", json::array({{{"name", "bark"},
                                  {"pbrMetallicRoughness",
                                   {{"baseColorFactor", {0.45, 0.32, 0.20, 1.0}},
                                    {"metallicFactor", 0.0},
                                    {"roughnessFactor", 0.9}}}},
                                 {{"name", "leaf"},
                                  {"doubleSided", true},
                                  {"pbrMetallicRoughness",
                                   {{"baseColorFactor", {0.25, 0.55, 0.15, 1.0}},
                                    {"metallicFactor", 0.0},
                                    {"roughnessFactor", 0.7}}}}})},
  };
  // glTF forbids empty arrays and meshes without primitives: an empty tree is a scene without
  // a mesh.
  if (primitives.empty()) {
    doc["nodes"] = json::array({json::object({{"name", "tree"}})});
  } else {
    doc["nodes"] = json::array({{{"mesh", 0}, {"name", "tree"}}});
    doc["meshes"] = json::array(
        {{{"name", "tree"}, {"primitives", primitives}, {"extras", {{"fspm_attributes", names}}}}});
    doc["buffers"] = json::array({{{"byteLength", bin_size}}});
    doc["bufferViews"] = buffer_views;
    doc["accessors"] = accessors;
  }
  std::string text = doc.dump();
  text.append((4 - text.size() % 4) % 4, ' ');

  const bool has_bin = !primitives.empty();
  const std::uint32_t total =
      static_cast<std::uint32_t>(12 + 8 + text.size() + (has_bin ? 8 + bin_size : 0));
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        auto u32 = [&](std::uint32_t x) { out.write(reinterpret_cast<const char*>(&x), 4); };
        u32(kGlbMagic);
        u32(2);
        u32(total);
        u32(static_cast<std::uint32_t>(text.size()));
        u32(kChunkJson);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        if (!has_bin) return;
        u32(static_cast<std::uint32_t>(bin_size));
        u32(kChunkBin);
        const char zeros[4] = {0, 0, 0, 0};
        for (const View& v : views) {
          out.write(static_cast<const char*>(v.data), static_cast<std::streamsize>(v.bytes));
          out.write(zeros,
                    static_cast<std::streamsize>(((v.bytes + 3) & ~std::size_t{3}) - v.bytes));
        }
      },
      true);
}

}  // namespace fspm::graphics
