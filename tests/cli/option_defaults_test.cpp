// The defaults the command line shows and uses are the library's: each option bound into a
// parameter struct prints, in --help, the value of a default-constructed struct's member. A CLI
// default typed again by hand that drifts from the struct (or an option that stops showing its
// default) fails here. The defaults are read from fspm-full's --help (CLI11's formatter over the
// options' bound values) and compared with the structs constructed in this test.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "environment/daylight.hpp"
#include "environment/growth_params.hpp"
#include "environment/light_model_registry.hpp"
#include "environment/sky.hpp"
#include "environment/sky_radiation.hpp"
#include "experiments/slurm_script.hpp"
#include "fspm/image_request.hpp"
#include "fspm/statistics.hpp"
#include "graphics/foliage.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "graphics/wind_animation.hpp"
#include "greenlab/calibration.hpp"
#include "scan_decoding/decoding.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"
#include "stages/developmental_model.hpp"
#include "stages/growth_profile.hpp"
#include "tests/cli/run_command.hpp"
#include "tests/cli/shell_output.hpp"
#ifdef FSPM_HAVE_CROWN
#include "crown/crown_from_photo.hpp"
#endif

namespace fspm {
namespace {

namespace fs = std::filesystem;
using testing::shell_output;

std::string full_exe() { return (fs::path(FSPM_EXE).parent_path() / "fspm-full").string(); }

// fspm-full's --help of a command path, run once per path.
const std::string& help_of(const std::string& command_path) {
  static std::map<std::string, std::string> cache;
  if (const auto it = cache.find(command_path); it != cache.end()) return it->second;
  int status = -1;
  std::string help = shell_output(full_exe() + " " + command_path + " --help", status);
  EXPECT_EQ(status, 0) << command_path;
  return cache[command_path] = std::move(help);
}

// The default --help shows for `option` of `command_path`: the word after the first '=' on the
// option's entry ("  --fps FLOAT:in (0, 1000]=24 Keyframes ..."), or "" when it shows none.
std::string shown_default(const std::string& command_path, const std::string& option) {
  std::istringstream in(help_of(command_path));
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 3 || line[0] != ' ' || line[2] == ' ') continue;  // not an entry
    std::istringstream words(line);
    std::string names;
    words >> names;
    std::istringstream each(names);
    bool match = false;
    for (std::string name; std::getline(each, name, ',');) match = match || name == option;
    if (!match) continue;
    const std::size_t eq = line.find('=', 2 + names.size());
    if (eq == std::string::npos) return {};
    const std::size_t end = line.find(' ', eq);
    return line.substr(eq + 1, end == std::string::npos ? std::string::npos : end - eq - 1);
  }
  ADD_FAILURE() << command_path << ": no option " << option;
  return {};
}

// A number as --help prints it (6 significant digits) against the struct's value.
void expect_number(const std::string& command_path, const std::string& option, double value) {
  const std::string shown = shown_default(command_path, option);
  ASSERT_FALSE(shown.empty()) << command_path << " " << option << " shows no default";
  const double parsed = std::stod(shown);
  EXPECT_NEAR(parsed, value, 1e-5 * std::max(1.0, std::abs(value)))
      << command_path << " " << option << " shows " << shown;
}

// The description of `option` of `command_path` in --help (on the entry's line, or on the next
// line when the option's names and type fill the first column), or "" when there is none.
std::string description_of(const std::string& command_path, const std::string& option) {
  std::istringstream in(help_of(command_path));
  std::string line;
  bool found = false;
  while (std::getline(in, line)) {
    if (found) return line;  // the continuation line of a long entry
    if (line.size() < 3 || line[0] != ' ' || line[2] == ' ') continue;  // not an entry
    std::istringstream words(line);
    std::string names;
    words >> names;
    std::istringstream each(names);
    for (std::string name; std::getline(each, name, ',');) found = found || name == option;
    if (!found) continue;
    const std::size_t text = line.find("  ", 2 + names.size());
    if (text != std::string::npos && line.find_first_not_of(' ', text) != std::string::npos) {
      return line;
    }
  }
  if (!found) ADD_FAILURE() << command_path << ": no option " << option;
  return {};
}

// An option whose default comes from an input file states the library's default in its text.
void expect_stated(const std::string& command_path, const std::string& option,
                   const std::string& stated) {
  const std::string text = description_of(command_path, option);
  EXPECT_NE(text.find(stated), std::string::npos)
      << command_path << " " << option << ": expected \"" << stated << "\" in: " << text;
}

void expect_text(const std::string& command_path, const std::string& option,
                 const std::string& value) {
  EXPECT_EQ(shown_default(command_path, option), value) << command_path << " " << option;
}

// mesh, render and view bind into MeshOptions (and the wind's options).
void expect_mesh_defaults(const std::string& command) {
  const graphics::MeshOptions m;
  expect_number(command, "--axis-subdivisions", m.axis_subdivisions);
  expect_number(command, "--seed", static_cast<double>(m.foliage_seed));
  expect_text(command, "--foliage", std::string(graphics::kFoliageModeNames.name(m.foliage.mode)));
}

TEST(OptionDefaults, MeshRenderAndViewShowTheLibraryDefaults) {
  const graphics::MeshOptions m;
  const graphics::WindOptions w;
  for (const char* command : {"mesh", "render", "view"}) expect_mesh_defaults(command);
  expect_number("mesh", "--edge-length", m.edge_length_m);
  expect_number("mesh", "--max-sides", m.max_sides);
  expect_text("mesh", "--junctions", std::string(graphics::junction_mode_name(m.junctions)));
  expect_number("mesh", "--wind-frequency", w.frequency_hz);
  for (const char* command : {"mesh", "render", "view"}) {
    expect_number(command, "--wind-amplitude", w.amplitude_rad * 180.0 / std::numbers::pi);
  }
  expect_number("mesh", "--fps", w.frames_per_second);

  const graphics::RenderOptions r;
  expect_number("render", "--edge-length", m.edge_length_m);
  expect_text("render", "--view", std::string(view_name(r.view)));
  expect_text("render", "--size", std::to_string(r.width) + "x" + std::to_string(r.height));
  expect_number("render", "--wind-period", w.duration_s);

  const graphics::ViewerOptions v;
  expect_number("view", "--max-sides", m.max_sides);
  expect_number("view", "--pitch-deg", v.pitch_deg);
  expect_number("view", "--yaw-deg", v.yaw_deg);
  expect_number("view", "--shadow-cascades", v.shadow_cascades);
  expect_text("view", "--size", std::to_string(v.width) + "x" + std::to_string(v.height));
}

TEST(OptionDefaults, ScanEncodeAndDecodeShowTheLibraryDefaults) {
  const scans::EncodeOptions e;
  expect_number("encode", "--neighbours", e.neighbours);
  expect_number("encode", "--main-branch-share", e.main_branch_share);
  expect_number("encode", "--main-branch-reach", e.main_branch_reach);

  const scans::ScanOptions s;
  expect_number("scan", "--scanners", s.scanners);
  expect_number("scan", "--density", s.density_per_m2);
  expect_number("scan", "--noise-mm", s.range_noise_m * 1000.0);
  expect_number("scan", "--min-radius", s.min_radius_m);

  const scan_decoding::DecodeOptions d;
  const scan_decoding::DecodeMeshOptions dm;
  expect_number("decode", "--branchlets", d.library.branchlets);
  expect_number("decode", "--prune-distance", dm.prune_distance_m);
  expect_number("decode", "--seed", static_cast<double>(d.seed));
}

#ifdef FSPM_HAVE_CROWN
TEST(OptionDefaults, CrownShowsTheLibraryDefaults) {
  const crown::CrownOptions c;
  expect_number("crown", "--height-m", c.height_m);
  expect_number("crown", "--depth-ratio", c.depth_ratio);
  expect_number("crown", "--relief", c.relief_weight);
  expect_number("crown", "--k", c.inflation.k);
  expect_number("crown", "--connectivity",
                c.inflation.connectivity == crown::Connectivity::kFour ? 4 : 8);
}
#endif

TEST(OptionDefaults, LightStagesAndTheRestShowTheLibraryDefaults) {
  const environment::RealSky sky;
  expect_number("light", "--elevation", sky.site.elevation_m);
  expect_number("light", "--utc-offset", sky.site.utc_offset_h);
  expect_number("light", "--transmittance", sky.transmittance);
  const std::string hours = shown_default("light", "--hours");
  const std::size_t colon = hours.find(':');
  ASSERT_NE(colon, std::string::npos) << hours;
  EXPECT_EQ(std::stod(hours.substr(0, colon)), sky.first_hour);
  EXPECT_EQ(std::stod(hours.substr(colon + 1)), sky.last_hour);
  expect_text("light", "--diffuse-sky",
              std::string(environment::kDiffuseSkyNames.name(sky.diffuse)));
  expect_text("light", "--split", std::string(environment::kDiffuseSplitNames.name(sky.split)));

  expect_stated("light", "--directions",
                "sky.directions, " + std::to_string(environment::Sky{}.directions) + ")");
  const environment::GrowthParams grow;
  expect_stated("grow", "--max-internodes",
                "max_internodes of the parameters, " + std::to_string(grow.max_internodes) + ")");
  expect_stated("grow", "--light-model",
                "; default " + std::string(environment::bud_light_model_name(grow.light_model)));
  expect_stated("grow", "--tropisms",
                "; default " + std::string(environment::tropism_pairing_name(
                                   environment::kDefaultTropismPairing)));

  const stages::StagesParams st;
  expect_number("stages", "--added-gamma", st.added.gamma);
  expect_text("stages", "--growth-profiles",
              std::string(stages::kProfileChoiceNames.name(st.profiles)));

  expect_number("greenlab fit", "--max-iterations", greenlab::FitOptions{}.max_iterations);
  const experiments::SlurmOptions slurm;
  expect_number("run", "--shards", static_cast<double>(slurm.shards));
  expect_text("run", "--slurm-time", slurm.time_limit);
  expect_number("stats ttest", "--level", kDefaultConfidenceLevel);
  expect_number("stats describe", "--level", kDefaultConfidenceLevel);
}

}  // namespace
}  // namespace fspm
