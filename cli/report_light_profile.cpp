#include "cli/report_light_profile.hpp"

#include <cstdio>
#include <filesystem>
#include <map>

#include "environment/leaf_light.hpp"
#include "experiments/render_selection.hpp"
#include "experiments/report_notes.hpp"
#include "fspm/error.hpp"
#include "graphics/chart_figure.hpp"

namespace fspm::cli {

namespace fs = std::filesystem;
namespace ex = fspm::experiments;

LightProfiles light_profiles(const ex::Experiment& x, const std::vector<ex::RunRecord>& runs,
                             const std::string& dir) {
  LightProfiles out;
  const std::vector<ex::RenderChoice> choices = ex::select_renders(x, runs);
  std::map<std::size_t, const ex::RunRecord*> by_run;
  for (const ex::RunRecord& r : runs) by_run[r.run] = &r;
  for (const ex::RenderChoice& c : choices) {
    try {
      TreeGraph tree = ex::recorded_run_tree(x, *by_run.at(c.run), dir);
      // Only leaf clusters that carry their translucency (Pirk eq. 4.4) shade as a crown does.
      if (!tree.has_attribute("translucency")) continue;
      // The leaves' light evaluated here, through the crown and the obstacles of the run's
      // scene, as the growth model records it (64 directions): a stored attribute may come from
      // another scene or an older file.
      environment::Scene scene =
          ex::recorded_run_scene(x, *by_run.at(c.run)).value_or(environment::Scene{});
      scene.sky.directions = 64;
      environment::record_leaf_light(tree, scene);
      std::vector<environment::LightLayer> layers = environment::leaf_light_profile(tree);
      if (layers.empty()) continue;
      out.trees.push_back({c.run, c.group, std::move(layers)});
    } catch (const Error& e) {
      out.notes.push_back("no light profile (run " + std::to_string(c.run) + "): " + e.what());
    }
  }
  return out;
}

std::string light_profile_explanation() {
  return "The mean light of the selected trees' leaf clusters (the mean light of each cluster's "
         "leaves through the crown as turbid media and past the obstacles of the run's scene, as "
         "a share of the open sky: 1 is a leaf that sees the whole sky) in ten layers from the "
         "lowest cluster to the highest, against the layer's height above the tree's base.";
}

std::string light_profile_figure(const ex::Experiment& x, const std::vector<ex::RunRecord>& runs,
                                 const std::string& dir) {
  const LightProfiles profiles = light_profiles(x, runs, dir);
  if (profiles.trees.empty()) return ex::notes_markdown(profiles.notes);
  std::vector<graphics::ChartSeries> series;
  std::string groups;
  for (const TreeLightProfile& t : profiles.trees) {
    graphics::ChartSeries s;
    // Short legend entries (the legend sits in the chart's upper right); the groups are listed
    // under the figure.
    s.name = "run " + std::to_string(t.run);
    groups += "- run " + std::to_string(t.run) + ": " + t.group + "\n";
    s.markers = true;
    for (const environment::LightLayer& layer : t.layers) {
      s.x.push_back(layer.mean_light);
      s.y.push_back(layer.height_m);
    }
    series.push_back(std::move(s));
  }
  const std::string file = "figures/light-profile.png";
  try {
    fs::create_directories(fs::path(dir) / "figures");
    graphics::ChartOptions options;
    options.title = "Light in the crown";
    options.x_label = "mean light of the leaf clusters (share of the open sky)";
    options.y_label = "height above the base (m)";
    options.width = 640;
    options.height = 480;
    // The whole range of the share, 0 to 1: profiles compare across reports, and the legend
    // (upper right) stays clear of the crowns' light, which rarely reaches 0.7
    // (docs/environment.md).
    for (int k = 0; k <= 10; ++k) {
      options.x_ticks.push_back(0.1 * k);
      char label[8];
      std::snprintf(label, sizeof label, "%.1f", 0.1 * k);
      options.x_tick_labels.emplace_back(label);
    }
    graphics::write_line_chart(series, options, (fs::path(dir) / file).string());
  } catch (const Error& e) {
    return "\nNote: light profile left out: " + std::string(e.what()) + "\n";
  } catch (const fs::filesystem_error& e) {
    return "\nNote: light profile left out: " + std::string(e.what()) + "\n";
  }
  return "\n## Light in the crown\n\n" + light_profile_explanation() +
         "\n\n![light against height in the crown](" + file + ")\n\n" + groups +
         ex::notes_markdown(profiles.notes);
}

}  // namespace fspm::cli
