#include "cli/report_light_profile.hpp"

#include <cstdio>
#include <filesystem>
#include <map>

#include "environment/leaf_light.hpp"
#include "environment/light_profile.hpp"
#include "experiments/render_selection.hpp"
#include "experiments/report_notes.hpp"
#include "fspm/error.hpp"
#include "graphics/chart_figure.hpp"

namespace fspm::cli {

namespace fs = std::filesystem;
namespace ex = fspm::experiments;

std::string light_profile_figure(const ex::Experiment& x, const std::vector<ex::RunRecord>& runs,
                                 const std::string& dir) {
  const std::vector<ex::RenderChoice> choices = ex::select_renders(x, runs);
  if (choices.empty()) return {};
  std::map<std::size_t, const ex::RunRecord*> by_run;
  for (const ex::RunRecord& r : runs) by_run[r.run] = &r;
  std::vector<graphics::ChartSeries> series;
  std::vector<std::string> notes;
  std::string groups;
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
      const std::vector<environment::LightLayer> profile = environment::leaf_light_profile(tree);
      if (profile.empty()) continue;
      graphics::ChartSeries s;
      // Short legend entries (the legend sits in the chart's upper right); the groups are listed
      // under the figure.
      s.name = "run " + std::to_string(c.run);
      groups += "- run " + std::to_string(c.run) + ": " + c.group + "\n";
      s.markers = true;
      for (const environment::LightLayer& layer : profile) {
        s.x.push_back(layer.mean_light);
        s.y.push_back(layer.height_m);
      }
      series.push_back(std::move(s));
    } catch (const Error& e) {
      notes.push_back("no light profile (run " + std::to_string(c.run) + "): " + e.what());
    }
  }
  if (series.empty()) return ex::notes_markdown(notes);
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
  return "\n## Light in the crown\n\nThe mean light of the selected trees' leaf clusters (the "
         "mean light of each cluster's leaves through the crown as turbid media and past the "
         "obstacles of the run's scene, as a share of the open sky) in ten layers from the lowest "
         "cluster to the highest, against the layer's height above the tree's base.\n\n![light "
         "against height in the crown](" +
         file + ")\n\n" + groups + ex::notes_markdown(notes);
}

}  // namespace fspm::cli
