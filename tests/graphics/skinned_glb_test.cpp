// The skinned, animated .glb read back by a minimal reader written here: chunk layout, accessor
// counts and types, joint indices below the joint count, normalised weights, inverse bind
// matrices and the rest pose of the joint nodes against the tree, the wind animation's
// channels.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "graphics/mesh_writers.hpp"
#include "graphics/skeleton_skin.hpp"
#include "graphics/wind_animation.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

struct Glb {
  nlohmann::json json;
  std::string bin;

  // The bytes of accessor i (tightly packed: no byteStride is written).
  const char* data(std::size_t i) const {
    const auto& a = json["accessors"][i];
    const auto& v = json["bufferViews"][a["bufferView"].get<std::size_t>()];
    return bin.data() + v["byteOffset"].get<std::size_t>() + a.value("byteOffset", 0);
  }
  template <class T>
  std::vector<T> values(std::size_t i, std::size_t per_element) const {
    const std::size_t n = json["accessors"][i]["count"].get<std::size_t>() * per_element;
    std::vector<T> out(n);
    std::memcpy(out.data(), data(i), n * sizeof(T));
    return out;
  }
};

Glb read_glb(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto u32 = [&](std::size_t at) {
    std::uint32_t x = 0;
    std::memcpy(&x, bytes.data() + at, 4);
    return x;
  };
  EXPECT_EQ(u32(0), 0x46546C67u);  // "glTF"
  EXPECT_EQ(u32(4), 2u);
  EXPECT_EQ(u32(8), bytes.size());
  const std::uint32_t json_length = u32(12);
  EXPECT_EQ(u32(16), 0x4E4F534Au);  // JSON
  Glb g;
  g.json = nlohmann::json::parse(bytes.substr(20, json_length));
  const std::size_t bin_at = 20 + json_length;
  EXPECT_EQ(u32(bin_at + 4), 0x004E4942u);  // BIN
  g.bin = bytes.substr(bin_at + 8, u32(bin_at));
  return g;
}

class SkinnedGlb : public ::testing::Test {
 protected:
  void SetUp() override {
    tree_ = testing::junction_tree();
    MeshOptions o;
    o.junctions = JunctionMode::kContinuous;
    mesh_ = mesh_tree(tree_, o);
    const Skin skin = skin_mesh(tree_, mesh_);
    WindOptions w;
    w.duration_s = 1.0;
    w.frames_per_second = 10.0;
    const WindAnimation wind = wind_animation(skin.skeleton, w);
    path_ = (std::filesystem::path(::testing::TempDir()) / "skinned.glb").string();
    write_skinned_glb(mesh_, skin, &wind, path_);
    glb_ = read_glb(path_);
  }
  TreeGraph tree_;
  TriangleMesh mesh_;
  std::string path_;
  Glb glb_;
};

TEST_F(SkinnedGlb, AccessorsFitTheMeshAndTheBuffer) {
  const auto& j = glb_.json;
  for (const auto& v : j["bufferViews"]) {
    EXPECT_LE(v["byteOffset"].get<std::size_t>() + v["byteLength"].get<std::size_t>(),
              glb_.bin.size());
  }
  const auto& attributes = j["meshes"][0]["primitives"][0]["attributes"];
  const std::size_t nv = mesh_.vertex_count();
  for (const char* name : {"POSITION", "JOINTS_0", "WEIGHTS_0"}) {
    EXPECT_EQ(j["accessors"][attributes[name].get<std::size_t>()]["count"], nv) << name;
  }
  const auto& joints_acc = j["accessors"][attributes["JOINTS_0"].get<std::size_t>()];
  EXPECT_EQ(joints_acc["componentType"], 5123);  // unsigned short
  EXPECT_EQ(joints_acc["type"], "VEC4");
  const std::size_t joint_count = j["skins"][0]["joints"].size();
  EXPECT_EQ(joint_count, 8u);  // the internodes
  const auto joints = glb_.values<std::uint16_t>(attributes["JOINTS_0"], 4);
  const auto weights = glb_.values<float>(attributes["WEIGHTS_0"], 4);
  for (std::size_t v = 0; v < nv; ++v) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      EXPECT_LT(joints[4 * v + k], joint_count);
      EXPECT_GE(weights[4 * v + k], 0.0f);
      sum += weights[4 * v + k];
    }
    ASSERT_NEAR(sum, 1.0f, 1e-6f) << "vertex " << v;
  }
  // The skinned mesh node stands at the scene root (glTF ignores its parents' transforms).
  bool mesh_at_root = false;
  for (const auto& n : j["scenes"][0]["nodes"]) {
    mesh_at_root |= j["nodes"][n.get<std::size_t>()].contains("skin");
  }
  EXPECT_TRUE(mesh_at_root);
}

TEST_F(SkinnedGlb, BindPoseMatchesTheTree) {
  const auto& j = glb_.json;
  const auto& skin = j["skins"][0];
  const auto ibm = glb_.values<float>(skin["inverseBindMatrices"], 16);
  // World position of each node from the translations down the node hierarchy.
  std::vector<Eigen::Vector3f> world(j["nodes"].size(), Eigen::Vector3f::Zero());
  std::vector<int> parent(j["nodes"].size(), -1);
  for (std::size_t n = 0; n < j["nodes"].size(); ++n) {
    for (const auto& c : j["nodes"][n].value("children", nlohmann::json::array())) {
      parent[c.get<std::size_t>()] = static_cast<int>(n);
    }
  }
  for (std::size_t i = 0; i < skin["joints"].size(); ++i) {
    const std::size_t node = skin["joints"][i];
    Eigen::Vector3f p = Eigen::Vector3f::Zero();
    for (int n = static_cast<int>(node); n >= 0; n = parent[n]) {
      const auto t = j["nodes"][n].value("translation", std::vector<float>{0, 0, 0});
      p += Eigen::Vector3f(t[0], t[1], t[2]);
    }
    const std::string name = j["nodes"][node]["name"];
    const NodeId id = static_cast<NodeId>(std::stoul(name.substr(name.find('_') + 1)));
    const Eigen::Vector3f head = tree_.start(id).cast<float>();
    EXPECT_TRUE(p.isApprox(head, 1e-5f) || (p - head).norm() < 1e-6f) << name;
    Eigen::Matrix4f m;
    std::memcpy(m.data(), ibm.data() + 16 * i, 64);  // column-major
    const Eigen::Vector4f origin = m * Eigen::Vector4f(head.x(), head.y(), head.z(), 1.0f);
    EXPECT_LT((origin - Eigen::Vector4f(0, 0, 0, 1)).norm(), 1e-5f)
        << "inverse bind of " << name << " takes its head to the origin";
    const Eigen::Matrix3f linear = m.block<3, 3>(0, 0);
    EXPECT_TRUE(linear.isIdentity(1e-6f));
  }
}

TEST_F(SkinnedGlb, WindAnimatesEveryJointWithUnitQuaternions) {
  const auto& j = glb_.json;
  const auto& anim = j["animations"][0];
  const auto& joints = j["skins"][0]["joints"];
  ASSERT_EQ(anim["channels"].size(), joints.size());
  std::set<std::size_t> targets;
  for (const auto& c : anim["channels"]) {
    EXPECT_EQ(c["target"]["path"], "rotation");
    targets.insert(c["target"]["node"].get<std::size_t>());
    const auto& s = anim["samplers"][c["sampler"].get<std::size_t>()];
    const auto& input = j["accessors"][s["input"].get<std::size_t>()];
    EXPECT_EQ(input["count"], 11);  // 0, 0.1, ..., 1 s
    EXPECT_FLOAT_EQ(input["min"][0].get<float>(), 0.0f);
    EXPECT_FLOAT_EQ(input["max"][0].get<float>(), 1.0f);
    EXPECT_EQ(j["accessors"][s["output"].get<std::size_t>()]["count"], 11);
    const auto q = glb_.values<float>(s["output"], 4);
    for (std::size_t k = 0; k < 11; ++k) {
      const Eigen::Vector4f quat(q[4 * k], q[4 * k + 1], q[4 * k + 2], q[4 * k + 3]);
      EXPECT_NEAR(quat.norm(), 1.0f, 1e-5f);
    }
  }
  for (const auto& n : joints) EXPECT_TRUE(targets.count(n.get<std::size_t>()));
}

}  // namespace
}  // namespace fspm::graphics
