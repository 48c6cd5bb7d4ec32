// fspm scene upgrade: scene files of an earlier layout rewritten in the current one.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "fspm/input_file.hpp"
#include "fspm/json_fields.hpp"
#include "fspm/scene_reader.hpp"
#include "fspm/scene_writer.hpp"

namespace fspm::cli {
namespace {

struct UpgradeOptions {
  std::string input;
  std::string out;
  bool json = false;
};

// The layout the file is written in: "current", or the earlier one the reader accepted
// (docs/formats.md, "Earlier layouts").
std::string scene_layout(const std::string& path) {
  const nlohmann::json doc = parse_json_text(read_text_input_file(path), path);
  if (!doc.contains("fspm_scene")) return "occluders";
  return doc.at("fspm_scene") == kSceneVersion ? "current" : "instances";
}

void run_upgrade(const UpgradeOptions& o) {
  refuse_overwriting_input(o.out, {o.input});
  const SceneDescription scene = read_scene_description(o.input);
  const std::string layout = scene_layout(o.input);
  write_scene_description(scene, o.out);
  if (o.json) {
    print_json({{"file", o.input},
                {"output", o.out},
                {"layout", layout},
                {"obstacles", scene.obstacles.size()},
                {"ground", scene.ground.has_value()},
                {"plants", scene.plants.size()}});
    return;
  }
  spdlog::info("wrote {} ({} obstacles, {} plants{}){}", o.out, scene.obstacles.size(),
               scene.plants.size(), scene.ground ? ", ground" : "",
               layout == "current" ? "; the input was already in the current layout"
                                   : "; upgraded from the earlier '" + layout + "' layout");
}

}  // namespace

void add_scene_commands(CLI::App& app) {
  CLI::App* scene = app.add_subcommand("scene", "Scene files (docs/formats.md)");
  scene->require_subcommand(1);
  auto upgrade = std::make_shared<UpgradeOptions>();
  CLI::App* u = scene->add_subcommand(
      "upgrade",
      "Rewrite a scene file of an earlier layout (growth scene with occluders, or plant scene "
      "with instances) in the current one; plant files stay where they are");
  u->add_option("SCENE", upgrade->input, "Scene file (.json)")->required();
  u->add_option("-o,--output", upgrade->out, "The upgraded scene (.json, not SCENE itself)")
      ->required();
  u->add_flag("--json", upgrade->json, "Machine-readable JSON on stdout");
  u->callback([upgrade] { run_reporting_command([&] { run_upgrade(*upgrade); }); });
}

}  // namespace fspm::cli
