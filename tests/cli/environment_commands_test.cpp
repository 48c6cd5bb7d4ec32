// fspm light and fspm grow, run as a user would.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;
using testing::write_text;

// An opaque sphere of radius 1 at height 3 over the first point: light cos^3(alpha) with
// sin(alpha) = 1/3 (closed form, see docs/environment.md); the second point is far outside every
// shadow volume and gets exactly 1.
TEST(EnvironmentCli, LightMatchesClosedFormAndKeepsRowOrder) {
  const auto dir = scratch_dir("light");
  write_text(dir / "scene.json",
             R"({"sky": {"brightest": [0, 0, 1]}, "occluders": [)"
             R"({"type": "sphere", "center": [0, 0, 3], "radius": 1, "translucency": 0}]})");
  write_text(dir / "points.csv", "x,y,z\n0,0,0\n100,100,0\n");
  const auto r = run_fspm("light --scene " + (dir / "scene.json").string() + " --points " +
                          (dir / "points.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  std::string header, row1, row2;
  std::getline(in, header);
  std::getline(in, row1);
  std::getline(in, row2);
  EXPECT_EQ(header, "x,y,z,light,dx,dy,dz");
  double x, y, z, light, dx, dy, dz;
  char c;
  std::istringstream(row1) >> x >> c >> y >> c >> z >> c >> light >> c >> dx >> c >> dy >> c >> dz;
  EXPECT_NEAR(light, std::pow(std::sqrt(8.0 / 9.0), 3), 1e-9);
  EXPECT_NEAR(dz, 1.0, 1e-9);
  std::istringstream(row2) >> x >> c >> y >> c >> z >> c >> light;
  EXPECT_EQ(x, 100.0);
  EXPECT_EQ(light, 1.0);

  const auto out = dir / "out.csv";
  const auto w = run_fspm("light --scene " + (dir / "scene.json").string() + " --points " +
                          (dir / "points.csv").string() + " --directions 64 -o " + out.string());
  ASSERT_EQ(w.exit_code, 0) << w.err;
  EXPECT_TRUE(std::filesystem::exists(out));
}

// The README's example: the scene is symmetric about the plane y = 0, so the light direction at a
// point of that plane has dy = 0 exactly; the sum over sky directions leaves about 1e-18 of
// rounding noise, written as 0.
TEST(EnvironmentCli, LightDirectionNoiseIsWrittenAsZero) {
  const std::string examples = std::string(FSPM_SOURCE_DIR) + "/examples/environment/";
  const auto r = run_fspm("light --scene " + examples + "sphere_and_box_scene.json --points " +
                          examples + "points.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  ASSERT_TRUE(row.starts_with("0,0,0,")) << row;
  std::vector<std::string> cells;
  std::istringstream fields(row);
  for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
  ASSERT_EQ(cells.size(), 7u) << row;
  EXPECT_EQ(cells[5], "0") << row;
}

TEST(EnvironmentCli, LightBadInputNamesFileAndPlace) {
  const auto dir = scratch_dir("light_bad");
  write_text(dir / "scene.json",
             R"({"occluders": [{"type": "sphere", "center": [0, 0, 3], "radius": -1}]})");
  write_text(dir / "ok.json", R"({"occluders": []})");
  write_text(dir / "points.csv", "x,y,z\n0,0,0\n1,oops,2\n");
  auto r = run_fspm("light --scene " + (dir / "scene.json").string() + " --points " +
                    (dir / "points.csv").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("/occluders/0/radius"), std::string::npos) << r.err;
  r = run_fspm("light --scene " + (dir / "ok.json").string() + " --points " +
               (dir / "points.csv").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("points.csv:3"), std::string::npos) << r.err;
}

// A real sky: an open point under a held global radiation of 400 W m-2 from 9 to 15 h (the sun up
// at 45 N in June) gets 400 * 0.5 * 4.57 umol m-2 s-1 and 6 h of it in mol m-2; a site without a
// date is refused.
TEST(EnvironmentCli, LightUnderARealSkyGivesPar) {
  const auto dir = scratch_dir("light_real_sky");
  write_text(dir / "scene.json", R"({"occluders": []})");
  write_text(dir / "points.csv", "x,y,z\n0,0,0\n");
  const std::string base = "light --scene " + (dir / "scene.json").string() + " --points " +
                           (dir / "points.csv").string() + " --latitude 45 --longitude 7";
  const auto r = run_fspm(base +
                          " --utc-offset 1 --date 2024-06-21 --hours 9:15 --global-radiation 400 "
                          "--json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double par = 400.0 * 0.5 * 4.57;
  EXPECT_NEAR(j["samples"][0]["par_umol_m2_s"].get<double>(), par, 1e-9);
  EXPECT_NEAR(j["samples"][0]["daily_par_mol_m2"].get<double>(), par * 6 * 3600 * 1e-6, 1e-9);
  const auto csv = run_fspm(base + " --utc-offset 1 --date 2024-06-21");
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')),
            "x,y,z,light,dx,dy,dz,par_umol_m2_s,daily_par_mol_m2");
  const auto bad = run_fspm(base);
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("--date"), std::string::npos) << bad.err;
  // Measured hours: 400 W m-2 from 9 to 15 h in a CSV is the held value above, with either split.
  std::string hours = "hour,global_W_m2\n";
  for (int h = 9; h < 15; ++h) hours += std::to_string(h) + ",400\n";
  write_text(dir / "day.csv", hours);
  const auto m = run_fspm(base + " --utc-offset 1 --date 2024-06-21 --split erbs --json " +
                          "--global-radiation-csv " + (dir / "day.csv").string());
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_NEAR(nlohmann::json::parse(m.out)["samples"][0]["daily_par_mol_m2"].get<double>(),
              par * 6 * 3600 * 1e-6, 1e-9);
  write_text(dir / "bad.csv", "hour,global_W_m2\n25,1\n");
  const auto b =
      run_fspm(base + " --date 2024-06-21 --global-radiation-csv " + (dir / "bad.csv").string());
  EXPECT_EQ(b.exit_code, 1);
  EXPECT_NE(b.err.find("bad.csv:2"), std::string::npos) << b.err;
}

// A grown tree's leaf clusters under a held global radiation of 400 W m-2 from 9 to 15 h: one row
// per cluster, each getting less than the open sky's 400 * 0.5 * 4.57 umol m-2 s-1 and more than
// nothing, its daily PAR 6 h of its mean; --points and --tree together are refused.
TEST(EnvironmentCli, LightOfATreesLeafClusters) {
  const auto dir = scratch_dir("light_tree");
  write_text(dir / "scene.json", R"({"occluders": []})");
  const auto tree = dir / "t.tree";
  ASSERT_EQ(run_fspm("grow --preset A --years 8 -o " + tree.string()).exit_code, 0);
  const auto info = nlohmann::json::parse(run_fspm("tree info --json " + tree.string()).out);
  const std::string base = "light --scene " + (dir / "scene.json").string();
  const auto r = run_fspm(base + " --tree " + tree.string() +
                          " --latitude 45 --longitude 7 --utc-offset 1 --date 2024-06-21 "
                          "--hours 9:15 --global-radiation 400 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["points"], info["leaves"]);
  const double open = 400.0 * 0.5 * 4.57;
  double darkest = open;
  for (const auto& s : j["samples"]) {
    const double par = s["par_umol_m2_s"].get<double>();
    EXPECT_GT(par, 0.0);
    EXPECT_LT(par, open);
    EXPECT_NEAR(s["daily_par_mol_m2"].get<double>(), par * 6 * 3600 * 1e-6, 1e-9);
    darkest = std::min(darkest, par);
  }
  EXPECT_LT(darkest, 0.5 * open);  // the crown shades its inside
  write_text(dir / "points.csv", "x,y,z\n0,0,0\n");
  const auto both =
      run_fspm(base + " --tree " + tree.string() + " --points " + (dir / "points.csv").string());
  EXPECT_EQ(both.exit_code, 1);
  EXPECT_NE(both.err.find("either --points or --tree"), std::string::npos) << both.err;
}

TEST(EnvironmentCli, GrowPresetWritesTreeAndJson) {
  const auto dir = scratch_dir("grow");
  const auto tree = dir / "a.tree";
  const auto r = run_fspm("grow --preset A --years 8 --seed 4 -o " + tree.string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["internodes"].get<int>(), 10);
  EXPECT_GE(j["clusters"].get<int>(), 1);
  EXPECT_GE(j["shed"].get<int>(), 0);
  EXPECT_GT(j["height"].get<double>(), 0.0);
  EXPECT_GE(j["seconds"].get<double>(), 0.0);
  EXPECT_TRUE(std::filesystem::exists(tree));
  // Same seed, same tree.
  const auto again = run_fspm("grow --preset A --years 8 --seed 4 -o " + tree.string() + " --json");
  EXPECT_EQ(nlohmann::json::parse(again.out)["internodes"], j["internodes"]);
}

TEST(EnvironmentCli, GrowChoosesTheLightModelOfAPreset) {
  const auto dir = scratch_dir("grow_models");
  const std::string out = " -o " + (dir / "t.tree").string() + " --json";
  for (const char* model : {"sky", "shadow_grid", "space_colonization"}) {
    const auto r = run_fspm(std::string("grow --preset A --years 6 --light-model ") + model + out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["light_model"], model);
  }
  EXPECT_EQ(nlohmann::json::parse(run_fspm("grow --preset A --years 6" + out).out)["light_model"],
            "shadow_grid");
  auto r = run_fspm("grow --preset A --light-model voxels" + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("light_model"), std::string::npos) << r.err;
  r = run_fspm("grow --preset B --tropisms captions" + out);
  EXPECT_EQ(r.exit_code, 1);
  write_text(dir / "p.toml", "years = 3\n");
  r = run_fspm("grow " + (dir / "p.toml").string() + " --light-model sky" + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("light_model"), std::string::npos) << r.err;
  // A model of adaptation only in a file: the registry's refusal naming the use, at its line.
  write_text(dir / "c.toml", "years = 3\nlight_model = \"canopy\"\n");
  r = run_fspm("grow " + (dir / "c.toml").string() + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("c.toml:2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("light_model 'canopy' gives no light to buds (growth): expected sky, "
                       "shadow_grid or space_colonization"),
            std::string::npos)
      << r.err;
}

TEST(EnvironmentCli, GrowBadInput) {
  const auto dir = scratch_dir("grow_bad");
  write_text(dir / "p.toml", "years = 5\nbranching = 3\n");
  auto r = run_fspm("grow " + (dir / "p.toml").string() + " -o " + (dir / "t.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("p.toml:2"), std::string::npos) << r.err;
  r = run_fspm("grow --preset Q -o " + (dir / "t.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  r = run_fspm("grow -o " + (dir / "t.tree").string());
  EXPECT_EQ(r.exit_code, 1);
}

// A parameter that makes the tree explode: one line naming where the parameters came from, the
// size reached and the limit, before the light model runs out of voxels (tests/environment,
// GrowthLimits, has the sizes).
TEST(EnvironmentCli, ExplodingGrowthNamesTheParametersAndTheLimit) {
  const auto dir = scratch_dir("grow_explode");
  const std::string out = (dir / "t.tree").string();
  auto r = run_fspm("grow --preset B --set apical_control=0.9 --years 30 -o " + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("preset B --set apical_control=0.9: growth stopped after year "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("above max_height_m = 150 m"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("voxel"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  r = run_fspm("grow --preset A --years 10 --max-internodes 50 -o " + out);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("preset A: growth stopped after year "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("above max_internodes = 50;"), std::string::npos) << r.err;
  EXPECT_NE(run_fspm("grow --preset A --max-internodes 0 -o " + out).exit_code, 0);
}

}  // namespace
}  // namespace fspm

namespace fspm {
namespace {

TEST(GrowCli, SetOverridesAnyParameterOverThePresetOrTheFile) {
  const auto dir = testing::scratch_dir("grow_set");
  const std::string out = (dir / "t.tree").string();
  const auto plain = testing::run_fspm("grow --preset B --years 6 --json -o " + out);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto set = testing::run_fspm(
      "grow --preset B --set years=6 --set apical_control=0.95 --set light_model=sky --json -o " +
      out);
  ASSERT_EQ(set.exit_code, 0) << set.err;
  const auto jp = nlohmann::json::parse(plain.out), js = nlohmann::json::parse(set.out);
  EXPECT_EQ(js["years"], 6);
  EXPECT_EQ(js["light_model"], "sky");
  EXPECT_NE(js["internodes"], jp["internodes"]);
  // Over a file: the file's years replaced.
  testing::write_text(dir / "p.toml", "preset = \"A\"\nyears = 4\n");
  const auto file =
      testing::run_fspm("grow " + (dir / "p.toml").string() + " --set years=2 --json -o " + out);
  ASSERT_EQ(file.exit_code, 0) << file.err;
  EXPECT_EQ(nlohmann::json::parse(file.out)["years"], 2);
  const auto unknown = testing::run_fspm("grow --preset B --set apical_contrl=0.6 -o " + out);
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.err.find("apical_contrl"), std::string::npos) << unknown.err;
  EXPECT_EQ(testing::run_fspm("grow --preset B --set apical_control=2 -o " + out).exit_code, 1);
  EXPECT_EQ(testing::run_fspm("grow --preset B --set nonsense -o " + out).exit_code, 1);
}

}  // namespace
}  // namespace fspm

namespace fspm {
namespace {

TEST(EnvironmentCli, LightJsonSummarizesTheSamples) {
  const auto dir = testing::scratch_dir("light_json");
  testing::write_text(dir / "open.json", R"({"occluders": []})");
  testing::write_text(dir / "p.csv", "x,y,z\n0,0,1\n3,1,2\n-1,4,0.5\n");
  const std::string base = "light --scene " + (dir / "open.json").string() + " --points " +
                           (dir / "p.csv").string() + " --json";
  const auto r = testing::run_fspm(base);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // Under an open sky every point gets all of it, from the zenith.
  EXPECT_EQ(j["points"], 3);
  EXPECT_NEAR(j["mean_light"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(j["min_light"].get<double>(), 1.0, 1e-12);
  ASSERT_EQ(j["samples"].size(), 3u);
  EXPECT_EQ(j["samples"][1]["point"][0], 3.0);
  EXPECT_NEAR(j["samples"][2]["direction"][2].get<double>(), 1.0, 1e-9);
  // With -o the samples go to the file and the JSON names it.
  const auto w = testing::run_fspm(base + " -o " + (dir / "out.csv").string());
  ASSERT_EQ(w.exit_code, 0) << w.err;
  const auto jw = nlohmann::json::parse(w.out);
  EXPECT_FALSE(jw.contains("samples"));
  EXPECT_EQ(jw["output"], (dir / "out.csv").string());
  EXPECT_TRUE(std::filesystem::exists(dir / "out.csv"));
}

}  // namespace
}  // namespace fspm
