// fspm mesh | render | view with compressed plants (meshed per substructure), scene files of
// many plants and .pvd growth sequences in the viewer.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/cli/small_tree.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_fspm;
using testing::scratch_dir;
using testing::write_small_tree;
using testing::write_text;

// Leeuwenberg's model (examples/greenlab) without straightening: no effect depends on the
// absolute orientation, so the instanced plant is the explicit one (Jaeger 3.1.2).
std::string write_plant(const fs::path& dir) {
  std::string text = read_text(fs::path(FSPM_SOURCE_DIR) / "examples/greenlab/leeuwenberg.toml");
  const std::string from = "straightening = 0.1";
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  if (at != std::string::npos) text.replace(at, from.size(), "straightening = 0.0");
  write_text(dir / "plant.toml", text);
  const std::string ctree = (dir / "plant.ctree").string();
  const auto r = run_fspm("greenlab simulate " + (dir / "plant.toml").string() + " -o " + ctree);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return ctree;
}

nlohmann::json mesh_json(const std::string& args) {
  const auto r = run_fspm("mesh " + args + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

nlohmann::json glb_json(const fs::path& p) {
  const std::string data = read_text(p);
  std::uint32_t len = 0;
  if (data.size() < 20) return {};
  std::memcpy(&len, data.data() + 12, 4);
  return nlohmann::json::parse(data.substr(20, len));
}

TEST(GraphicsInstancingCli, CompressedPlantMeshesLikeItsExplicitReconstruction) {
  const auto dir = scratch_dir("inst_plant");
  const std::string ctree = write_plant(dir);
  const std::string tree = (dir / "plant.tree").string();
  ASSERT_EQ(run_fspm("greenlab reconstruct " + ctree + " -o " + tree).exit_code, 0);
  for (const char* leaves : {"", " --leaves"}) {
    const auto inst = mesh_json(ctree + " -o " + (dir / "i.glb").string() + leaves);
    const auto expl = mesh_json(tree + " -o " + (dir / "e.glb").string() + leaves);
    EXPECT_EQ(inst["triangles"], expl["triangles"]) << leaves;
    EXPECT_EQ(inst["vertices"], expl["vertices"]) << leaves;
    EXPECT_GT(inst["instances"].get<std::size_t>(), 10 * inst["meshes"].get<std::size_t>());
    EXPECT_LT(inst["stored_triangles"].get<std::size_t>(), expl["triangles"].get<std::size_t>());
    EXPECT_LT(fs::file_size(dir / "i.glb"), fs::file_size(dir / "e.glb") / 4);
    if (*leaves == '\0') {  // bark only: bounds agree up to the turn of rings about their axis
      for (const char* side : {"min", "max"}) {
        for (int k = 0; k < 3; ++k) {
          EXPECT_NEAR(inst["bounds"][side][k].get<double>(), expl["bounds"][side][k].get<double>(),
                      0.01)
              << side << k;
        }
      }
    }
  }
  // The .glb keeps the instancing: one glTF mesh per substructure, one node per occurrence.
  mesh_json(ctree + " -o " + (dir / "i.glb").string());
  const auto inst = mesh_json(ctree + " -o " + (dir / "i.glb").string());
  const auto doc = glb_json(dir / "i.glb");
  EXPECT_EQ(doc["meshes"].size(), inst["meshes"].get<std::size_t>());
  std::size_t referencing = 0;
  for (const auto& n : doc["nodes"]) referencing += n.contains("mesh") ? 1 : 0;
  EXPECT_EQ(referencing, inst["instances"].get<std::size_t>());
  // A plant description is simulated on the fly to the same plant.
  const auto from_toml =
      mesh_json((dir / "plant.toml").string() + " -o " + (dir / "t.obj").string());
  EXPECT_EQ(from_toml["triangles"], inst["triangles"]);
}

TEST(GraphicsInstancingCli, SceneOfTwoHundredTreesFromTwoFiles) {
  const auto dir = scratch_dir("inst_scene");
  const std::string ctree = write_plant(dir);
  TreeGraph t;
  NodeData d;
  d.end = {0, 0, 1};
  d.radius = 0.05;
  t.add_node(kNoNode, d);
  write_tree_file(t, (dir / "pole.tree").string());
  const auto plant = mesh_json(ctree + " -o " + (dir / "p.glb").string());
  const auto pole = mesh_json((dir / "pole.tree").string() + " -o " + (dir / "q.glb").string());
  // Jaeger 4.2's forest: 200 trees from two graphs, on a 20 x 10 grid, turned and scaled.
  fs::create_directories(dir / "scenes");
  nlohmann::json instances = nlohmann::json::array();
  for (int i = 0; i < 200; ++i) {
    instances.push_back({{"file", i % 2 ? "../pole.tree" : "../plant.ctree"},
                         {"position", {12.0 * (i % 20), 12.0 * (i / 20), 0.0}},
                         {"rotation_deg", 17.0 * i},
                         {"scale", 0.8 + 0.002 * i}});
  }
  const fs::path scene = dir / "scenes" / "forest.json";
  write_text(scene, nlohmann::json({{"fspm_scene", 1}, {"instances", instances}}).dump(1));
  const auto j = mesh_json(scene.string() + " -o " + (dir / "forest.glb").string());
  const auto tri = [](const nlohmann::json& x) { return x["triangles"].get<std::size_t>(); };
  EXPECT_EQ(tri(j), 100 * tri(plant) + 100 * tri(pole));
  EXPECT_EQ(j["meshes"], plant["meshes"].get<std::size_t>() + 1);
  EXPECT_EQ(j["instances"], 100 * plant["instances"].get<std::size_t>() + 100);
  EXPECT_EQ(glb_json(dir / "forest.glb")["meshes"].size(), j["meshes"].get<std::size_t>());
  // The grid spans 19 x 9 spacings plus a tree on each side.
  EXPECT_GT(j["bounds"]["max"][0].get<double>() - j["bounds"]["min"][0].get<double>(), 19 * 12.0);
  EXPECT_LT(fs::file_size(dir / "forest.glb"), 100 * fs::file_size(dir / "p.glb"));

  auto r = run_fspm("render " + scene.string() + " -o " + (dir / "forest.png").string() +
                    " --size 160x120 --json");
  if (r.err.find("without VTK") == std::string::npos) {
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], tri(j));
    EXPECT_TRUE(fs::exists(dir / "forest.png"));
    r = run_fspm("render " + scene.string() + " -o " + (dir / "plan.png").string() +
                 " --size 160x120 --view top --ortho-height 150");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "plan.png"));
    r = run_fspm("render " + scene.string() + " -o " + (dir / "bad.png").string() +
                 " --ortho-height -1");
    EXPECT_NE(r.exit_code, 0);
    EXPECT_FALSE(fs::exists(dir / "bad.png"));
  }
}

// --lod draws fewer triangles than the full scene for a row of plants seen from afar, in renders
// and in the viewer, and refuses what it does not combine with.
TEST(GraphicsInstancingCli, LevelOfDetailDrawsFewerTriangles) {
  const auto dir = scratch_dir("inst_lod");
  write_small_tree(dir);
  nlohmann::json plants = nlohmann::json::array();
  for (int i = 0; i < 20; ++i)
    plants.push_back({{"file", "t.tree"}, {"position", {5.0 * i, 0, 0}}});
  const fs::path scene = dir / "row.json";
  write_text(scene, nlohmann::json({{"fspm_scene", 2}, {"plants", plants}}).dump());
  const auto full = mesh_json(scene.string() + " --leaves -o " + (dir / "row.glb").string());
  const auto all = full["triangles"].get<std::size_t>();
  auto r = run_fspm("render " + scene.string() + " --leaves --lod -o " +
                    (dir / "row.png").string() + " --size 160x120 --json");
  if (r.err.find("without VTK") == std::string::npos &&
      r.err.find("no X display") == std::string::npos) {
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["plants"], 20);
    EXPECT_GT(j["triangles"].get<std::size_t>(), 0u);
    EXPECT_LT(j["triangles"].get<std::size_t>(), all);
    EXPECT_TRUE(fs::exists(dir / "row.png"));
  }
  r = run_fspm("view " + scene.string() + " --leaves --lod --screenshot " +
               (dir / "v.png").string() + " --frames 2 --size 160x120 --json");
  if (r.err.find("without") == std::string::npos) {
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_GT(j["triangles"].get<std::size_t>(), 0u);
    EXPECT_LT(j["triangles"].get<std::size_t>(), all);
  }
  r = run_fspm("view " + scene.string() + " --lod --ages 1 --screenshot " +
               (dir / "w.png").string());
  EXPECT_EQ(r.exit_code, 1);
  r = run_fspm("render " + scene.string() + " --lod --color-by age -o " + (dir / "c.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "c.png"));
}

TEST(GraphicsInstancingCli, BadScenesFailCleanly) {
  const auto dir = scratch_dir("inst_bad");
  write_text(dir / "broken.json", "{\"instances\": [\n  {\"file\": }\n]}");
  auto r = run_fspm("mesh " + (dir / "broken.json").string() + " -o " + (dir / "out.glb").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("broken.json:2"), std::string::npos) << r.err;
  write_text(dir / "missing.json", R"({"instances": [{"file": "nowhere.ctree"}]})");
  r = run_fspm("mesh " + (dir / "missing.json").string() + " -o " + (dir / "out.glb").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("nowhere.ctree"), std::string::npos) << r.err;
  r = run_fspm("render " + (dir / "missing.json").string() + " -o " + (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "out.glb"));
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(GraphicsInstancingCli, ViewerStepsThroughAPvdSequence) {
  const auto dir = scratch_dir("inst_pvd");
  TreeGraph t;
  NodeData d;
  d.radius = 0.05;
  NodeId parent = kNoNode;
  for (int i = 0; i < 3; ++i) {  // three internodes up z, born 0, 1, 2
    d.start = {0, 0, static_cast<double>(i)};
    d.end = {0, 0, i + 1.0};
    d.birth_time = i;
    parent = t.add_node(parent, d);
  }
  const std::string tree = (dir / "t.tree").string();
  write_tree_file(t, tree);
  const auto seq = mesh_json(tree + " -o " + (dir / "growth.pvd").string() + " --ages 0,1,2");
  ASSERT_EQ(seq["frames"].size(), 3u);
  auto r = run_fspm("view " + (dir / "growth.pvd").string() + " --screenshot " +
                    (dir / "v.png").string() + " --frames 2 --size 160x120 --json");
  if (r.err.find("without the viewer") != std::string::npos ||
      r.err.find("without VTK") != std::string::npos ||
      r.err.find("without OpenImageIO") != std::string::npos) {
    GTEST_SKIP() << r.err;
  }
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["steps"], 3);
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(j["triangles"], seq["frames"][2]["triangles"]);  // starts on the last step
  EXPECT_TRUE(fs::exists(dir / "v.png"));
  r = run_fspm("view " + (dir / "growth.pvd").string() + " --ages 1 --screenshot " +
               (dir / "w.png").string());
  EXPECT_EQ(r.exit_code, 1);
  write_text(dir / "bad.pvd", "<VTKFile type=\"Collection\"><Collection></Collection></VTKFile>");
  r = run_fspm("view " + (dir / "bad.pvd").string() + " --screenshot " + (dir / "w.png").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir / "w.png"));
}

}  // namespace
}  // namespace fspm
