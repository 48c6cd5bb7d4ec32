#pragma once
// Hand-made glTF 2.0 files for the reader tests (glTF 2.0 spec. sec. 3.6 buffers and accessors,
// sec. 4.4 the GLB container): meshes of float positions and 32-bit indices, one node each, with
// an optional transform, written as .gltf (the buffer as a base64 data URI, RFC 4648) or .glb.
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace fspm::scans::test {

struct GltfPart {
  std::string node_name;  // empty: the node has no name
  std::string mesh_name;
  std::vector<float> positions;  // x y z per vertex
  std::vector<std::uint32_t> indices;
  nlohmann::json transform = nlohmann::json::object();  // "translation", "rotation", ...
  int mode = 4;                                         // 4 triangles, 0 points
};

inline std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t v = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 2]);
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kDigits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
  }
  return out;
}

// The glTF JSON of `parts` (root nodes in order, or all children of one root node with
// `root_transform` when it is not empty) and its binary buffer.
inline std::pair<nlohmann::json, std::string> gltf_of(const std::vector<GltfPart>& parts,
                                                      const nlohmann::json& root_transform = {}) {
  using nlohmann::json;
  json nodes = json::array(), meshes = json::array(), views = json::array(),
       accessors = json::array();
  std::string bin;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const GltfPart& p = parts[k];
    std::array<float, 3> lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
    for (std::size_t i = 0; i < p.positions.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], p.positions[i]);
      hi[i % 3] = std::max(hi[i % 3], p.positions[i]);
    }
    views.push_back(
        {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", 4 * p.positions.size()}});
    bin.append(reinterpret_cast<const char*>(p.positions.data()), 4 * p.positions.size());
    views.push_back(
        {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", 4 * p.indices.size()}});
    bin.append(reinterpret_cast<const char*>(p.indices.data()), 4 * p.indices.size());
    accessors.push_back({{"bufferView", 2 * k},
                         {"componentType", 5126},
                         {"count", p.positions.size() / 3},
                         {"type", "VEC3"},
                         {"min", lo},
                         {"max", hi}});
    accessors.push_back({{"bufferView", 2 * k + 1},
                         {"componentType", 5125},
                         {"count", p.indices.size()},
                         {"type", "SCALAR"}});
    meshes.push_back(
        {{"name", p.mesh_name},
         {"primitives",
          {{{"attributes", {{"POSITION", 2 * k}}}, {"indices", 2 * k + 1}, {"mode", p.mode}}}}});
    json node = p.transform;
    node["mesh"] = k;
    if (!p.node_name.empty()) node["name"] = p.node_name;
    nodes.push_back(node);
  }
  json scene_nodes = json::array();
  if (root_transform.is_null()) {
    for (std::size_t k = 0; k < parts.size(); ++k) scene_nodes.push_back(k);
  } else {
    json root = root_transform;
    root["name"] = "root";
    root["children"] = json::array();
    for (std::size_t k = 0; k < parts.size(); ++k) root["children"].push_back(k);
    scene_nodes.push_back(nodes.size());
    nodes.push_back(root);
  }
  json g = {{"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", scene_nodes}}}},
            {"nodes", nodes},
            {"meshes", meshes},
            {"bufferViews", views},
            {"accessors", accessors},
            {"buffers", {{{"byteLength", bin.size()}}}}};
  return {g, bin};
}

inline void write_gltf(const std::string& path, const std::vector<GltfPart>& parts,
                       const nlohmann::json& root_transform = {}) {
  auto [g, bin] = gltf_of(parts, root_transform);
  g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
  std::ofstream(path, std::ios::binary) << g.dump();
}

// GLB: 12-byte header, a JSON chunk padded with spaces and a BIN chunk padded with zeros to
// multiples of four bytes (glTF 2.0 sec. 4.4).
inline void write_glb(const std::string& path, const std::vector<GltfPart>& parts,
                      const nlohmann::json& root_transform = {}) {
  auto [g, bin] = gltf_of(parts, root_transform);
  std::string json_text = g.dump();
  while (json_text.size() % 4 != 0) json_text += ' ';
  while (bin.size() % 4 != 0) bin += '\0';
  std::string out;
  const auto u32 = [&out](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  u32(0x46546C67);  // "glTF"
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + json_text.size() + 8 + bin.size()));
  u32(static_cast<std::uint32_t>(json_text.size()));
  u32(0x4E4F534A);  // "JSON"
  out += json_text;
  u32(static_cast<std::uint32_t>(bin.size()));
  u32(0x004E4942);  // "BIN"
  out += bin;
  std::ofstream(path, std::ios::binary) << out;
}

// The unit cube [0, 1]^3: 8 corners, 12 triangles (two per side, outward).
inline GltfPart unit_cube(const std::string& node_name, const std::string& mesh_name) {
  GltfPart p{node_name, mesh_name, {}, {}};
  for (int i = 0; i < 8; ++i) {
    p.positions.insert(p.positions.end(),
                       {static_cast<float>(i & 1), static_cast<float>((i >> 1) & 1),
                        static_cast<float>((i >> 2) & 1)});
  }
  // Quads by corner bits (x = 1, y = 2, z = 4), each split along a diagonal.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    p.indices.insert(p.indices.end(),
                     {std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2]),
                      std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
  }
  return p;
}

}  // namespace fspm::scans::test
