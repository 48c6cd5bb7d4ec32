// fspm light | grow: sky light at points through a scene's occluders (Pirk eq. 4.3) and the
// self-organizing growth model (Palubicki et al. 2009) with Pirk's tree types A, B and C.
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/commands.hpp"
#include "cli/enum_option.hpp"
#include "cli/output.hpp"
#include "environment/canopy_light.hpp"
#include "environment/canopy_sweep.hpp"
#include "environment/daylight.hpp"
#include "environment/growth_model.hpp"
#include "environment/leaf_light.hpp"
#include "environment/light_model.hpp"
#include "environment/points_file.hpp"
#include "environment/radiation_file.hpp"
#include "environment/scene_file.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::cli {
namespace {

struct LightOptions {
  std::string scene;
  std::string points;
  std::string tree;  // instead of points: the tree's leaf clusters
  std::string out;
  int directions = 0;
  bool json = false;
  // A real sky (all optional; --latitude, --longitude and --date switch it on). The options
  // bound straight into it take its defaults.
  environment::RealSky sky;
  std::optional<double> latitude, longitude;
  std::string date;
  std::string hours = fmt::format("{:g}:{:g}", sky.first_hour, sky.last_hour);
  std::optional<double> global_W_m2;
  std::string global_csv;
};

// The real sky of the options, or none when no site and date were given.
std::optional<environment::RealSky> real_sky(const LightOptions& o) {
  const bool any = o.latitude || o.longitude || !o.date.empty();
  if (!any) return std::nullopt;
  if (!o.latitude || !o.longitude || o.date.empty()) {
    throw ValueError("a real sky needs --latitude, --longitude and --date together");
  }
  environment::RealSky sky = o.sky;
  sky.site.latitude_deg = *o.latitude;
  sky.site.longitude_deg = *o.longitude;
  sky.date = environment::parse_date(o.date);
  environment::parse_hours(o.hours, sky);
  if (o.global_W_m2 && !o.global_csv.empty()) {
    throw ValueError("--global-radiation and --global-radiation-csv exclude each other");
  }
  if (!o.global_csv.empty())
    sky.hourly_global_W_m2 = environment::read_hourly_global_csv(o.global_csv);
  if (o.global_W_m2) {
    if (*o.global_W_m2 < 0.0) throw ValueError("--global-radiation must be >= 0 W m-2");
    sky.global_W_m2 = *o.global_W_m2;
  }
  sky.validate();
  return sky;
}

// `fspm light --json`: counts, the light's range and mean, and the samples themselves when they
// are not written to a file.
nlohmann::json light_json(const LightOptions& o, const std::vector<Eigen::Vector3d>& points,
                          const std::vector<environment::LightSample>& samples,
                          const std::vector<environment::DaylightSample>& daylight,
                          double seconds) {
  double sum = 0.0, lo = 1.0, hi = 0.0;
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const environment::LightSample& s = samples[k];
    sum += s.light;
    lo = std::min(lo, s.light);
    hi = std::max(hi, s.light);
    if (o.out.empty()) {
      rows.push_back({{"point", {points[k].x(), points[k].y(), points[k].z()}},
                      {"light", s.light},
                      {"direction", {s.direction.x(), s.direction.y(), s.direction.z()}}});
      if (k < daylight.size()) {
        rows.back()["par_umol_m2_s"] = daylight[k].par_umol_m2_s;
        rows.back()["daily_par_mol_m2"] = daylight[k].daily_par_mol_m2;
      }
    }
  }
  nlohmann::json j = {{"scene", o.scene},
                      {"points", samples.size()},
                      {"mean_light", samples.empty() ? 0.0 : sum / samples.size()},
                      {"min_light", samples.empty() ? 0.0 : lo},
                      {"max_light", samples.empty() ? 0.0 : hi},
                      {"seconds", seconds}};
  if (!daylight.empty()) {
    double par = 0.0, mol = 0.0;
    for (const auto& d : daylight) par += d.par_umol_m2_s, mol += d.daily_par_mol_m2;
    j["mean_par_umol_m2_s"] = par / daylight.size();
    j["mean_daily_par_mol_m2"] = mol / daylight.size();
  }
  if (o.out.empty()) {
    j["samples"] = std::move(rows);
  } else {
    j["output"] = o.out;
  }
  return j;
}

struct GrowOptions {
  std::string params;
  std::string preset;
  std::string light_model;  // with --preset: the light model the preset is fitted for
  std::string tropisms;     // with --preset: "text" or "appendix"
  std::string scene;
  std::string out;
  std::string format;
  int years = -1;
  std::int64_t seed = -1;
  std::vector<std::string> settings;  // --set NAME=VALUE
  std::int64_t max_internodes = -1;   // -1: from the parameters
  bool json = false;
};

// The light of a tree's leaf clusters: the mean light of each cluster's leaves through the crown
// as turbid media and the scene's obstacles, as fspm grow records it (record_leaf_light: spheres,
// or kLeafLightVoxel_m voxels above kLeafLightVoxelsFrom clusters), and its PAR under a real sky
// as fspm grow records it too (record_leaf_par: the crown swept in kCanopySweepVoxel_m voxels).
void leaf_cluster_light(const LightOptions& o, const environment::Scene& scene,
                        const std::optional<environment::RealSky>& sky,
                        std::vector<Eigen::Vector3d>& points,
                        std::vector<environment::LightSample>& samples,
                        std::vector<environment::DaylightSample>& daylight) {
  const TreeGraph tree = read_tree_file(o.tree);
  std::vector<std::uint32_t> sphere_of;
  const std::vector<environment::Sphere> clusters = environment::leaf_spheres(tree, sphere_of);
  if (clusters.empty()) {
    throw ValueError(o.tree + ": expected leaf clusters (leaf nodes, as fspm grow writes them)");
  }
  for (const environment::Sphere& c : clusters) points.push_back(c.center);
  const double voxel_m =
      clusters.size() > environment::kLeafLightVoxelsFrom ? environment::kLeafLightVoxel_m : 0.0;
  const environment::CanopyLight light(scene, clusters, voxel_m);
  samples = light.evaluate_clusters();
  if (sky) {
    daylight = environment::daylight_through_voxels(clusters, scene, *sky, points,
                                                    environment::kCanopySweepVoxel_m);
  }
}

void run_light(const LightOptions& o) {
  if (o.points.empty() == o.tree.empty()) {
    throw ValueError("fspm light needs either --points or --tree");
  }
  refuse_overwriting_input(o.out, {o.scene, o.points, o.tree});
  environment::Scene scene = environment::read_scene_file(o.scene);
  if (o.directions != 0) scene.sky.directions = o.directions;  // checked by the LightModel
  const std::optional<environment::RealSky> sky = real_sky(o);
  std::vector<Eigen::Vector3d> points;
  std::vector<environment::LightSample> samples;
  std::vector<environment::DaylightSample> daylight;
  const auto t0 = std::chrono::steady_clock::now();
  if (!o.tree.empty()) {
    leaf_cluster_light(o, scene, sky, points, samples, daylight);
  } else {
    points = environment::read_points_csv(o.points);
    const environment::LightModel model(scene);
    samples.resize(points.size());
    model.evaluate(points, samples);
    if (sky) daylight = environment::daylight_at(environment::CanopyLight(scene, {}), *sky, points);
  }
  const double seconds = seconds_since(t0);
  spdlog::debug("light: {} points in {:.3f} s", points.size(), seconds);
  if (!o.out.empty()) {
    write_file_atomically(o.out, [&](std::ostream& out) {
      environment::write_light_csv(out, points, samples, daylight);
    });
    spdlog::info("wrote {} ({} points)", o.out, points.size());
  }
  if (o.json) {
    print_json(light_json(o, points, samples, daylight, seconds));
  } else if (o.out.empty()) {
    environment::write_light_csv(std::cout, points, samples, daylight);
    std::cout.flush();
  }
}

// The parameters of `fspm grow`: a file, or a preset fitted for --light-model with --tropisms.
environment::GrowthParams grow_params(const GrowOptions& o) {
  if (o.preset.empty() && (!o.light_model.empty() || !o.tropisms.empty())) {
    throw ValueError(
        "--light-model and --tropisms choose a preset; with PARAMS.toml, set "
        "light_model and preset_tropisms in the file");
  }
  environment::GrowthParams params;
  if (o.preset.empty()) {
    params = environment::read_growth_params(o.params, o.settings);
  } else {
    const auto model = o.light_model.empty()
                           ? environment::GrowthParams{}.light_model
                           : environment::bud_light_model_from_name(o.light_model);
    const auto pairing = o.tropisms.empty() ? environment::kDefaultTropismPairing
                                            : environment::tropism_pairing_from_name(o.tropisms);
    params = environment::growth_preset(o.preset, model, pairing);
    if (!o.settings.empty()) {
      // The preset as a parameter file, the settings over it.
      const std::string base = "preset = \"" + o.preset + "\"\nlight_model = \"" +
                               std::string(environment::bud_light_model_name(model)) +
                               "\"\npreset_tropisms = \"" +
                               std::string(environment::tropism_pairing_name(pairing)) + "\"\n";
      params = environment::parse_growth_params(base, "--preset", o.settings);
    }
  }
  if (o.years >= 0) params.years = o.years;
  if (o.seed >= 0) params.seed = static_cast<std::uint64_t>(o.seed);
  if (o.max_internodes > 0) params.max_internodes = static_cast<std::size_t>(o.max_internodes);
  return params;
}

void run_grow(const GrowOptions& o) {
  refuse_overwriting_input(o.out, {o.params, o.scene});
  if (o.params.empty() == o.preset.empty()) {
    throw ValueError("expected either a PARAMS.toml file or --preset A|B|C (not both)");
  }
  const environment::GrowthParams params = grow_params(o);
  environment::Scene scene;
  if (!o.scene.empty()) scene = environment::read_scene_file(o.scene);
  tree_format_for(o.out, o.format);  // fail on a bad output name before growing
  const auto t0 = std::chrono::steady_clock::now();
  environment::GrowthResult r;
  try {
    r = environment::grow_tree(params, scene);
  } catch (const environment::GrowthLimitError& e) {
    // The library names the parameters' values; the command line knows where they came from.
    std::string source = o.preset.empty() ? o.params : "preset " + o.preset;
    for (const std::string& s : o.settings) source += " --set " + s;
    throw environment::GrowthLimitError(source + ": " + e.message());
  }
  const double seconds = seconds_since(t0);
  write_tree_file(r.tree, o.out, o.format);
  if (o.json) {
    print_json({{"internodes", r.internodes},
                {"clusters", r.clusters},
                {"shed", r.shed},
                {"height", r.height_m},
                {"seconds", seconds},
                {"years", params.years},
                {"light_model", std::string(environment::bud_light_model_name(params.light_model))},
                {"output", o.out}});
    return;
  }
  spdlog::info("grew {} internodes ({} shed), {} leaf clusters, height {:.2f} m in {:.3f} s -> {}",
               r.internodes, r.shed, r.clusters, r.height_m, seconds, o.out);
}

}  // namespace

void add_environment_commands(CLI::App& app) {
  auto light = std::make_shared<LightOptions>();
  CLI::App* l = app.add_subcommand(
      "light", "Sky light (Pirk eq. 4.3) and mean light direction at points of a scene");
  l->add_option("--scene", light->scene, "Scene file (JSON, see docs/formats.md)")->required();
  l->add_option("--points", light->points, "Points (CSV with header x,y,z)");
  l->add_option("--tree", light->tree,
                "Instead of --points: a tree file whose leaf clusters get the mean light of their "
                "leaves through the crown (one row per cluster, at its centre)");
  l->add_option("--directions", light->directions,
                fmt::format("Stratified sky directions (default: the scene's sky.directions, {})",
                            environment::Sky{}.directions))
      ->check(number_in(1, kMaxSkyDirections));
  l->add_option("-o,--output", light->out, "Output CSV x,y,z,light,dx,dy,dz (default: stdout)");
  l->add_flag("--json", light->json,
              "One JSON object on stdout: points, mean/min/max light, seconds, and the samples "
              "unless -o writes them");
  l->add_option("--latitude", light->latitude,
                "Real sky: site latitude (degrees, north positive); with --longitude and --date "
                "adds PAR columns par_umol_m2_s and daily_par_mol_m2");
  l->add_option("--longitude", light->longitude,
                "Real sky: site longitude (degrees, east positive)");
  l->add_option("--elevation", light->sky.site.elevation_m, "Real sky: site elevation (m)")
      ->capture_default_str();
  l->add_option("--utc-offset", light->sky.site.utc_offset_h,
                "Real sky: local clock time minus UTC (hours)")
      ->capture_default_str();
  l->add_option("--date", light->date, "Real sky: date YYYY-MM-DD (1950-2050)");
  l->add_option("--hours", light->hours,
                "Real sky: local hours FROM:TO integrated (0:24: the whole day)")
      ->capture_default_str();
  add_enum_option(l, "--diffuse-sky", light->sky.diffuse, environment::kDiffuseSkyNames,
                  "Real sky: diffuse radiance");
  l->add_option("--global-radiation", light->global_W_m2,
                "Real sky: global radiation on a horizontal plane (W m-2) held while the sun is "
                "up (default: the clear sky of the site and date)");
  l->add_option("--global-radiation-csv", light->global_csv,
                "Real sky: measured hourly global radiation, CSV hour,global_W_m2 (local hours "
                "0-23)");
  add_enum_option(l, "--split", light->sky.split, environment::kDiffuseSplitNames,
                  "Real sky: direct/diffuse split of the global radiation");
  l->add_option("--transmittance", light->sky.transmittance,
                "Real sky: clear-sky atmospheric transmittance")
      ->capture_default_str();
  l->callback([light] { run_reporting_command([&] { run_light(*light); }); });

  auto grow = std::make_shared<GrowOptions>();
  CLI::App* g = app.add_subcommand(
      "grow", "Self-organizing tree growth (Palubicki 2009) with light, walls and obstacles");
  g->add_option("PARAMS", grow->params, "Growth parameters (TOML, see docs/environment.md)");
  g->add_option("--preset", grow->preset, "Pirk's tree type A, B or C instead of PARAMS");
  g->add_option(
      "--light-model", grow->light_model,
      "With --preset: " + environment::kBudLightModelNames.help() + "; default " +
          std::string(environment::bud_light_model_name(environment::GrowthParams{}.light_model)));
  g->add_option(
      "--tropisms", grow->tropisms,
      "With --preset: Pirk's tropism pairing, " + environment::kTropismPairingNames.help() +
          "; default " +
          std::string(environment::tropism_pairing_name(environment::kDefaultTropismPairing)));
  g->add_option("--scene", grow->scene, "Scene with obstacles and sky (JSON, see docs/formats.md)");
  g->add_option("--years", grow->years, "Growth cycles (default: from the parameters)")
      ->check(number_in(0, environment::kMaxYears));
  g->add_option("--seed", grow->seed, "Random seed (default: from the parameters)")
      ->check(number_in(0, kMaxSeed));
  g->add_option("--set", grow->settings,
                "NAME=VALUE: any parameter of docs/environment.md over the preset or PARAMS "
                "(repeatable), e.g. --set apical_control=0.6");
  g->add_option("--max-internodes", grow->max_internodes,
                fmt::format("Stop with a message when the tree has more internodes than this "
                            "(default: max_internodes of the parameters, {})",
                            environment::GrowthParams{}.max_internodes))
      ->check(number_in(1, 9e18));
  g->add_option("-o,--output", grow->out, "Output tree file (.tree, .treeb, .nwk, .mtg)")
      ->required();
  g->add_option("--format", grow->format, "Output format (default: from the extension)");
  g->add_flag("--json", grow->json, "Machine-readable JSON on stdout");
  g->callback([grow] { run_reporting_command([&] { run_grow(*grow); }); });
}

}  // namespace fspm::cli
