// Binary glTF 2.0 (.glb): one mesh with a primitive per material sharing the vertex accessors;
// an instanced scene stores each shared mesh once and references it from one node per instance.
// Attributes are application-specific vertex attributes (glTF 2.0 section 3.7.2.1: names start
// with an underscore), e.g. "age" -> "_AGE"; mesh.extras.fspm_attributes maps them back.
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {
namespace {

static_assert(std::endian::native == std::endian::little, "glTF writer assumes little endian");

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kUnsignedShort = 5123;
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

// Accumulates meshes into one binary buffer and glTF JSON, then writes the .glb.
class GlbBuilder {
 public:
  // Adds `mesh` as a glTF mesh with a primitive per material sharing the vertex accessors;
  // returns its index, or -1 for an empty mesh (glTF forbids meshes without primitives).
  long add_mesh(const TriangleMesh& mesh, const std::string& name,
                const nlohmann::json& extra_attributes = nlohmann::json::object()) {
    using nlohmann::json;
    const std::size_t nv = mesh.vertex_count();
    if (mesh.empty() || nv == 0) return -1;
    // Indices split by glTF material: the kMaterials order (bark, leaf, obstacle, crown,
    // translucent obstacle, terrain), then one material per translucency of translucent obstacles.
    auto& indices = index_store_.emplace_back();
    const std::vector<std::size_t> material_of = triangle_materials(mesh);
    for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
      auto& list = indices[material_of[i]];
      list.insert(list.end(), mesh.triangles[i].begin(), mesh.triangles[i].end());
    }
    json attributes = json::object();
    const Eigen::Vector3f lo = mesh.bbox_min();
    const Eigen::Vector3f hi = mesh.bbox_max();
    const std::size_t pos =
        add_accessor(add_view(mesh.positions.data(), nv * 12, kArrayBuffer), kFloat, nv, "VEC3");
    accessors_[pos]["min"] = {lo.x(), lo.y(), lo.z()};  // required for POSITION
    accessors_[pos]["max"] = {hi.x(), hi.y(), hi.z()};
    attributes["POSITION"] = pos;
    // Normals and texture coordinates are optional in glTF (viewers then shade flat): a mesh
    // without them (lightened for the web) leaves them out.
    if (mesh.normals.size() == nv) {
      attributes["NORMAL"] =
          add_accessor(add_view(mesh.normals.data(), nv * 12, kArrayBuffer), kFloat, nv, "VEC3");
    }
    if (mesh.uvs.size() == nv) {
      attributes["TEXCOORD_0"] =
          add_accessor(add_view(mesh.uvs.data(), nv * 8, kArrayBuffer), kFloat, nv, "VEC2");
    }
    // Per-vertex colours (a crown reconstructed from a photograph) as glTF's COLOR_0; vertices
    // without one (a tree placed beside the crown) take their material's.
    if (mesh.has_vertex_colors()) {
      auto& rgb = color_store_.emplace_back(3 * nv);
      const std::vector<std::array<float, 3>> colors = resolved_vertex_colors(mesh);
      for (std::size_t i = 0; i < nv; ++i) std::copy_n(colors[i].data(), 3, rgb.data() + 3 * i);
      attributes["COLOR_0"] =
          add_accessor(add_view(rgb.data(), nv * 12, kArrayBuffer), kFloat, nv, "VEC3");
    }
    json names = json::object();
    for (const auto& a : mesh.attributes) {
      const std::string key = gltf_attribute_name(a.name);
      attributes[key] =
          add_accessor(add_view(a.values.data(), nv * 4, kArrayBuffer), kFloat, nv, "SCALAR");
      names[key] = a.name;
    }
    attributes.update(extra_attributes);
    json primitives = json::array();
    for (const auto& [m, list] : indices) {
      if (list.empty()) continue;
      const std::size_t acc =
          add_accessor(add_view(list.data(), list.size() * 4, kElementArrayBuffer), kUnsignedInt,
                       list.size(), "SCALAR");
      primitives.push_back(
          {{"attributes", attributes}, {"indices", acc}, {"material", m}, {"mode", 4}});
    }
    meshes_.push_back(
        {{"name", name}, {"primitives", primitives}, {"extras", {{"fspm_attributes", names}}}});
    return static_cast<long>(meshes_.size() - 1);
  }

  // An accessor over data the builder keeps until the file is written (vertex data when
  // `vertex_data`, else skins and animations, which take no buffer view target).
  std::size_t add_floats(std::vector<float> data, std::size_t count, const char* type,
                         bool vertex_data = false) {
    const std::vector<float>& kept = float_store_.emplace_back(std::move(data));
    return add_accessor(add_view(kept.data(), kept.size() * 4, vertex_data ? kArrayBuffer : 0),
                        kFloat, count, type);
  }
  std::size_t add_shorts(std::vector<std::uint16_t> data, std::size_t count, const char* type) {
    const std::vector<std::uint16_t>& kept = short_store_.emplace_back(std::move(data));
    return add_accessor(add_view(kept.data(), kept.size() * 2, kArrayBuffer), kUnsignedShort, count,
                        type);
  }
  nlohmann::json& accessor(std::size_t i) { return accessors_[i]; }

  // Writes the file with `nodes` (each may reference a mesh) under one root node; `extra` adds
  // top-level arrays (skins, animations).
  void write(nlohmann::json nodes, const std::string& path,
             const nlohmann::json& extra = nlohmann::json::object()) {
    using nlohmann::json;
    json doc = {
        {"asset", {{"version", "2.0"}, {"generator", "fspm"}}},
        {"scene", 0},
        {"scenes", json::array({{{"nodes", json::array({0})}}})},
        {"materials", materials_json()},
        {"nodes", std::move(nodes)},
    };
    doc.update(extra);
    // glTF forbids empty arrays: an empty tree is a scene without a mesh.
    const bool has_bin = !meshes_.empty();
    if (has_bin) {
      doc["meshes"] = meshes_;
      doc["buffers"] = json::array({{{"byteLength", bin_size_}}});
      doc["bufferViews"] = buffer_views_;
      doc["accessors"] = accessors_;
    }
    std::string text = doc.dump();
    text.append((4 - text.size() % 4) % 4, ' ');
    const std::uint64_t total = 12 + 8 + text.size() + (has_bin ? 8 + bin_size_ : 0);
    if (total > std::numeric_limits<std::uint32_t>::max()) {
      throw ValueError("the .glb would be larger than 4 GiB, the format's limit", path);
    }
    write_file_atomically(
        path,
        [&](std::ostream& out) {
          auto u32 = [&](std::uint32_t x) { out.write(reinterpret_cast<const char*>(&x), 4); };
          u32(kGlbMagic);
          u32(2);
          u32(static_cast<std::uint32_t>(total));
          u32(static_cast<std::uint32_t>(text.size()));
          u32(kChunkJson);
          out.write(text.data(), static_cast<std::streamsize>(text.size()));
          if (!has_bin) return;
          u32(static_cast<std::uint32_t>(bin_size_));
          u32(kChunkBin);
          const char zeros[4] = {0, 0, 0, 0};
          for (const View& v : views_) {
            out.write(static_cast<const char*>(v.data), static_cast<std::streamsize>(v.bytes));
            out.write(zeros,
                      static_cast<std::streamsize>(((v.bytes + 3) & ~std::size_t{3}) - v.bytes));
          }
        },
        true);
  }

 private:
  struct View {
    const void* data;
    std::size_t bytes;
  };

  std::size_t add_view(const void* data, std::size_t bytes, int target) {
    buffer_views_.push_back({{"buffer", 0}, {"byteOffset", bin_size_}, {"byteLength", bytes}});
    if (target != 0) buffer_views_.back()["target"] = target;
    views_.push_back({data, bytes});
    bin_size_ += (bytes + 3) & ~std::size_t{3};
    return buffer_views_.size() - 1;
  }
  std::size_t add_accessor(std::size_t view, int component, std::size_t count, const char* type) {
    accessors_.push_back(
        {{"bufferView", view}, {"componentType", component}, {"count", count}, {"type", type}});
    return accessors_.size() - 1;
  }

  static double rounded(float x) { return std::round(1000.0 * x) / 1000.0; }  // 0.45, not 0.449999

  // The glTF material of each triangle: its fspm Material's index, or for a translucent obstacle
  // carrying the vertex attribute "translucency" the material of that translucency gamma (one
  // per distinct gamma in the file, after the kMaterials ones).
  std::vector<std::size_t> triangle_materials(const TriangleMesh& mesh) {
    std::vector<std::size_t> out(mesh.triangle_count());
    const bool gammas = mesh.has_attribute("translucency");
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Material m = i < mesh.materials.size() ? mesh.materials[i] : Material::kBark;
      out[i] = static_cast<std::size_t>(m);
      if (m != Material::kTranslucentObstacle || !gammas) continue;
      const float gamma = mesh.attribute("translucency")[mesh.triangles[i][0]];
      auto [it, added] = translucencies_.emplace(gamma, kMaterials.size() + translucencies_.size());
      out[i] = it->second;
    }
    return out;
  }

  // One glTF material per fspm Material, in the order of kMaterials (the primitives' index),
  // then one per translucency gamma of translucent obstacles: alpha 1 - gamma
  // (translucent_obstacle_opacity, as the renders draw them), blended.
  nlohmann::json materials_json() const {
    nlohmann::json out = base_materials_json();
    std::vector<std::pair<std::size_t, float>> extra;
    for (const auto& [gamma, index] : translucencies_) extra.emplace_back(index, gamma);
    std::sort(extra.begin(), extra.end());
    for (const auto& [index, gamma] : extra) {
      nlohmann::json material = out[static_cast<std::size_t>(Material::kTranslucentObstacle)];
      char name[64];
      std::snprintf(name, sizeof(name), "translucent_obstacle_%g", rounded(gamma));
      material["name"] = name;
      material["pbrMetallicRoughness"]["baseColorFactor"][3] =
          rounded(translucent_obstacle_opacity(gamma));
      material["extras"] = {{"translucency", rounded(gamma)}};
      out.push_back(std::move(material));
    }
    return out;
  }

  static nlohmann::json base_materials_json() {
    nlohmann::json out = nlohmann::json::array();
    for (Material m : kMaterials) {
      const std::array<float, 3> c = material_color(m);
      const double roughness = m == Material::kLeaf ? 0.7 : is_obstacle(m) ? 0.95 : 0.9;
      const double alpha = m == Material::kCrown ? rounded(kCrownOpacity)
                           : m == Material::kTranslucentObstacle
                               ? rounded(kTranslucentObstacleOpacity)
                               : 1.0;
      nlohmann::json material = {
          {"name", material_name(m)},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {rounded(c[0]), rounded(c[1]), rounded(c[2]), alpha}},
            {"metallicFactor", 0.0},
            {"roughnessFactor", roughness}}}};
      if (m == Material::kLeaf || m == Material::kCrown) material["doubleSided"] = true;
      if (alpha < 1.0) material["alphaMode"] = "BLEND";  // crowns and hedges seen through
      out.push_back(std::move(material));
    }
    return out;
  }

  std::vector<View> views_;
  std::deque<std::map<std::size_t, std::vector<std::uint32_t>>> index_store_;  // stable
  std::map<float, std::size_t> translucencies_;  // gamma -> glTF material
  std::deque<std::vector<float>> color_store_;   // stable addresses for COLOR_0 views
  std::deque<std::vector<float>> float_store_;
  std::deque<std::vector<std::uint16_t>> short_store_;
  nlohmann::json buffer_views_ = nlohmann::json::array();
  nlohmann::json accessors_ = nlohmann::json::array();
  nlohmann::json meshes_ = nlohmann::json::array();
  std::size_t bin_size_ = 0;
};

// JOINTS_0 and WEIGHTS_0 (glTF 2.0 section 3.7.3.3) of a skin.
nlohmann::json skin_attributes(GlbBuilder& glb, const Skin& skin) {
  const std::size_t nv = skin.joints.size();
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
  joints.reserve(4 * nv);
  weights.reserve(4 * nv);
  for (std::size_t v = 0; v < nv; ++v) {
    joints.insert(joints.end(), skin.joints[v].begin(), skin.joints[v].end());
    weights.insert(weights.end(), skin.weights[v].begin(), skin.weights[v].end());
  }
  return {{"JOINTS_0", glb.add_shorts(std::move(joints), nv, "VEC4")},
          {"WEIGHTS_0", glb.add_floats(std::move(weights), nv, "VEC4", true)}};
}

// Joint nodes from `first`: translation from the parent joint's head, children by index.
nlohmann::json joint_nodes(const Skeleton& s, std::size_t first) {
  nlohmann::json nodes = nlohmann::json::array();
  std::vector<std::vector<std::size_t>> children(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (s.parents[j] >= 0) children[static_cast<std::size_t>(s.parents[j])].push_back(first + j);
  }
  for (std::size_t j = 0; j < s.size(); ++j) {
    const int p = s.parents[j];
    const Eigen::Vector3f t = p < 0 ? s.heads_m[j] : Eigen::Vector3f(s.heads_m[j] - s.heads_m[p]);
    nlohmann::json node = {{"name", "joint_" + std::to_string(s.nodes[j])},
                           {"translation", {t.x(), t.y(), t.z()}}};
    if (!children[j].empty()) node["children"] = children[j];
    nodes.push_back(std::move(node));
  }
  return nodes;
}

// One sampler and one rotation channel per joint, sharing the keyframe times.
nlohmann::json animation_json(GlbBuilder& glb, const WindAnimation& a, std::size_t first_joint) {
  using nlohmann::json;
  const std::size_t frames = a.times_s.size();
  const std::size_t input = glb.add_floats(a.times_s, frames, "SCALAR");
  glb.accessor(input)["min"] = {a.times_s.front()};  // required for animation inputs
  glb.accessor(input)["max"] = {a.times_s.back()};
  json samplers = json::array(), channels = json::array();
  const std::size_t joints = frames == 0 ? 0 : a.frames.front().size();
  for (std::size_t j = 0; j < joints; ++j) {
    std::vector<float> xyzw;
    xyzw.reserve(4 * frames);
    for (const auto& frame : a.frames) {
      const Eigen::Vector4f q = frame[j].coeffs();  // x, y, z, w as glTF stores them
      xyzw.insert(xyzw.end(), q.data(), q.data() + 4);
    }
    const std::size_t output = glb.add_floats(std::move(xyzw), frames, "VEC4");
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    channels.push_back(
        {{"sampler", j}, {"target", {{"node", first_joint + j}, {"path", "rotation"}}}});
  }
  return {{"name", "wind"}, {"samplers", samplers}, {"channels", channels}};
}

}  // namespace

void write_skinned_glb(const TriangleMesh& mesh, const Skin& skin, const WindAnimation* wind,
                       const std::string& path) {
  using nlohmann::json;
  if (skin.joints.size() != mesh.vertex_count() || skin.skeleton.size() == 0) {
    throw ValueError("the skin does not belong to this mesh (or the tree has no internode)", path);
  }
  GlbBuilder glb;
  const long m = glb.add_mesh(mesh, "tree", skin_attributes(glb, skin));
  // Node 0 holds the root joints (from 2), so it is the skeleton's root; the skinned mesh node
  // (1) stands at the scene root beside it, since parent transforms do not move skinned meshes.
  constexpr std::size_t kFirstJoint = 2;
  json nodes = json::array({{{"name", "tree"}}, {{"name", "bark"}}});
  json roots = json::array();
  for (std::size_t j = 0; j < skin.skeleton.size(); ++j) {
    if (skin.skeleton.parents[j] < 0) roots.push_back(kFirstJoint + j);
  }
  if (!roots.empty()) nodes[0]["children"] = roots;
  for (auto& node : joint_nodes(skin.skeleton, kFirstJoint)) nodes.push_back(std::move(node));
  std::vector<float> ibm;
  for (const Eigen::Matrix4f& b : inverse_bind_matrices(skin.skeleton)) {
    ibm.insert(ibm.end(), b.data(), b.data() + 16);  // column-major
  }
  json joints = json::array();
  for (std::size_t j = 0; j < skin.skeleton.size(); ++j) joints.push_back(kFirstJoint + j);
  json extra = {
      {"scenes", json::array({{{"nodes", json::array({0, 1})}}})},
      {"skins", json::array({{{"name", "skeleton"},
                              {"skeleton", 0},
                              {"joints", joints},
                              {"inverseBindMatrices",
                               glb.add_floats(std::move(ibm), skin.skeleton.size(), "MAT4")}}})}};
  if (m >= 0) {
    nodes[1]["mesh"] = m;
    nodes[1]["skin"] = 0;
  }
  if (wind != nullptr && !wind->times_s.empty()) {
    extra["animations"] = json::array({animation_json(glb, *wind, kFirstJoint)});
  }
  glb.write(std::move(nodes), path, extra);
}

void write_glb(const TriangleMesh& mesh, const std::string& path) {
  GlbBuilder glb;
  const long m = glb.add_mesh(mesh, "tree");
  nlohmann::json node = {{"name", "tree"}};
  if (m >= 0) node["mesh"] = m;
  glb.write(nlohmann::json::array({node}), path);
}

void write_glb(const InstancedMesh& scene, const std::string& path) {
  using nlohmann::json;
  GlbBuilder glb;
  std::vector<long> index;
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const TriangleMesh& mesh = scene.meshes[i];
    const bool obstacles = mesh.triangle_count(Material::kObstacle) +
                               mesh.triangle_count(Material::kTranslucentObstacle) ==
                           mesh.triangle_count();
    index.push_back(
        glb.add_mesh(mesh, obstacles ? "obstacles" : "substructure_" + std::to_string(i)));
  }
  // Node 0 is the scene root; every instance is a child node referencing its shared mesh
  // (glTF 2.0 section 3.5: a mesh may be instantiated by many nodes).
  json nodes = json::array({{{"name", "scene"}}});
  json children = json::array();
  for (const MeshInstance& inst : scene.instances) {
    if (index[inst.mesh] < 0) continue;
    json node = {{"mesh", index[inst.mesh]}};
    const Eigen::Matrix4f m = inst.matrix();  // column-major, as glTF stores it
    if (!m.isIdentity()) node["matrix"] = std::vector<float>(m.data(), m.data() + 16);
    if (inst.order_offset != 0.0f) node["extras"] = {{"order_offset", inst.order_offset}};
    children.push_back(nodes.size());
    nodes.push_back(std::move(node));
  }
  if (!children.empty()) nodes[0]["children"] = std::move(children);
  glb.write(std::move(nodes), path);
}

}  // namespace fspm::graphics
