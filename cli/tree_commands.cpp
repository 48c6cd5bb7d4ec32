// fspm tree info | convert: inspect and convert tree graph files.
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "environment/canopy_summary.hpp"
#include "environment/leaf_light.hpp"
#include "environment/site_sky.hpp"
#include "environment/sky_distribution.hpp"
#include "fspm/attribute_names.hpp"
#include "fspm/error.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/plant_frame.hpp"
#include "fspm/tree_file.hpp"
#include "fspm/tree_summary.hpp"
#include "scans/grouped_mesh_skeleton.hpp"
#include "scans/mesh_file.hpp"

namespace fspm::cli {
namespace {

struct InfoOptions {
  std::string file;
  std::string format;
  bool json = false;
  std::string sky_file;  // a real sky (sky = { site, date, hours | days }) for the canopy light
};

struct ConvertOptions {
  std::string in;
  std::string out;
  std::string from;
  std::string to;
};

// Nodes flagged by plastic adaptation's "pruned" attribute (kept with fspm adapt --keep-pruned).
std::size_t pruned_count(const TreeGraph& tree) {
  const auto pruned = tree.attribute(kPrunedAttribute);
  return static_cast<std::size_t>(
      std::count_if(pruned.begin(), pruned.end(), [](double v) { return v != 0.0; }));
}

// The foliage of a tree with leaf clusters (leaf nodes and the attribute "translucency", as grown
// and adapted trees keep them) under a beam from the zenith (environment/canopy_summary).
std::optional<nlohmann::json> canopy_json(const TreeGraph& tree) {
  if (!tree.has_attribute("translucency")) return std::nullopt;
  std::vector<std::uint32_t> sphere_of;
  const std::vector<environment::Sphere> clusters = environment::leaf_spheres(tree, sphere_of);
  if (clusters.empty()) return std::nullopt;
  const environment::CanopySummary c = environment::summarize_canopy(clusters);
  return nlohmann::json{{"clusters", c.clusters},
                        {"beam", "zenith"},
                        {"leaf_area_m2", c.leaf_area_m2},
                        {"sunlit_leaf_area_m2", c.sunlit_leaf_area_m2},
                        {"shaded_leaf_area_m2", c.shaded_leaf_area_m2},
                        {"silhouette_area_m2", c.silhouette_area_m2},
                        {"star", c.star}};
}

nlohmann::json canopy_light_values(const environment::ClusterCanopyLight& c, bool real_sky) {
  nlohmann::json j = {{"leaf_area_m2", c.leaf_area_m2},
                      {"sunlit_leaf_area_m2", c.sunlit_leaf_area_m2},
                      {"shaded_leaf_area_m2", c.shaded_leaf_area_m2},
                      {"lie", c.lie},
                      {"star", c.star}};
  if (real_sky) j["absorbed_par_mol_day"] = c.absorbed_par_mol_day;
  return j;
}

// The light of the leaf clusters in the crown, per cluster and for the tree
// (environment/canopy_summary: summarize_canopy_light), under a real sky or eq. 4.3's cos^2 sky.
std::optional<nlohmann::json> canopy_light_json(const TreeGraph& tree,
                                                const std::string& sky_file) {
  if (!tree.has_attribute("translucency")) return std::nullopt;
  std::vector<std::uint32_t> sphere_of;
  const std::vector<environment::Sphere> clusters = environment::leaf_spheres(tree, sphere_of);
  if (clusters.empty()) return std::nullopt;
  environment::Sky sky;
  sky.directions = 64;  // the growth model's leaf light
  if (!sky_file.empty()) {
    environment::apply_sky_distribution(
        sky, std::make_shared<const environment::SkyDistribution>(
                 environment::sky_distribution(environment::read_site_sky_file(sky_file))));
  }
  const environment::CanopyLightSummary c = environment::summarize_canopy_light(clusters, sky);
  environment::ClusterCanopyLight total;
  total.leaf_area_m2 = c.leaf_area_m2;
  total.sunlit_leaf_area_m2 = c.sunlit_leaf_area_m2;
  total.shaded_leaf_area_m2 = c.shaded_leaf_area_m2;
  total.lie = c.lie;
  total.star = c.star;
  total.absorbed_par_mol_day = c.absorbed_par_mol_day;
  nlohmann::json j = canopy_light_values(total, c.real_sky);
  j["sky"] = c.real_sky ? "site" : "cos2";
  j["clusters"] = c.clusters;
  nlohmann::json per = nlohmann::json::array();
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (sphere_of[i] == environment::kNoSphere) continue;
    nlohmann::json v = canopy_light_values(c.per_cluster[sphere_of[i]], c.real_sky);
    v["node"] = i;
    per.push_back(std::move(v));
  }
  j["per_cluster"] = std::move(per);
  return j;
}

nlohmann::json summary_json(const std::string& file, const TreeGraph& tree) {
  const TreeSummary s = summarize(tree);
  nlohmann::json j = {{"file", file},
                      {"nodes", s.nodes},
                      {"internodes", s.internodes},
                      {"leaves", s.leaves},
                      {"flowers", s.flowers},
                      {"buds", s.buds},
                      {"tips", s.tips},
                      {"max_order", s.max_order},
                      {"max_depth", s.max_depth},
                      {"height", s.height_m},
                      {"total_length", s.total_length_m},
                      {"crown_width", s.crown_width_m},
                      {"crown_depth", s.crown_depth_m},
                      {"branches_per_order", s.branches_per_order},
                      {"bbox_min", {s.bbox_min.x(), s.bbox_min.y(), s.bbox_min.z()}},
                      {"bbox_max", {s.bbox_max.x(), s.bbox_max.y(), s.bbox_max.z()}},
                      {"attributes", tree.attribute_names()}};
  if (tree.has_attribute(kPrunedAttribute)) j["pruned"] = pruned_count(tree);
  // A measured plant (MTG) whose file lacks part of its geometry: how much was inferred.
  if (tree.has_attribute("inferred")) {
    const auto inferred = tree.attribute("inferred");
    std::size_t positions = 0, radii = 0;
    for (double v : inferred) {
      if (!(v >= 0.0 && v < 8.0)) continue;  // not the bits of an MTG import
      const auto bits = static_cast<unsigned>(v);
      positions += (bits & kInferredPosition) != 0;
      radii += (bits & kInferredRadius) != 0;
    }
    j["positions_inferred"] = positions;
    j["radii_inferred"] = radii;
  }
  if (const auto canopy = canopy_json(tree)) j["canopy"] = *canopy;
  return j;
}

void run_info(const InfoOptions& o) {
  const TreeGraph tree = read_tree_file(o.file, o.format);
  nlohmann::json j = summary_json(o.file, tree);
  if (const auto light = canopy_light_json(tree, o.sky_file)) {
    j["canopy_light"] = *light;
  } else if (!o.sky_file.empty()) {
    throw ValueError(o.file +
                     ": --sky needs leaf clusters (leaf nodes with translucency, as fspm "
                     "grow writes them)");
  }
  if (o.json) {
    print_json(j);
    return;
  }
  // Text for reading: lengths in metres to four significant digits, counts as they are.
  std::cout << o.file << '\n';
  for (const char* key : {"nodes", "internodes", "leaves", "flowers", "buds", "tips", "max_order",
                          "max_depth", "pruned", "positions_inferred", "radii_inferred"}) {
    if (j.contains(key)) std::cout << "  " << key << ": " << json_text(j[key]) << '\n';
  }
  for (const char* key : {"height", "total_length", "crown_width", "crown_depth"}) {
    std::cout << "  " << key << ": " << human_text(j[key]) << " m\n";
  }
  std::cout << "  branches_per_order: " << json_text(j["branches_per_order"]) << '\n';
  std::cout << "  attributes: " << json_text(j["attributes"]) << '\n';
  if (j.contains("canopy")) {
    const auto& c = j["canopy"];
    std::cout << fmt::format(
        "  canopy (beam from the zenith): {} clusters, leaf area {:.2f} m2, sunlit {:.2f} m2, "
        "shaded {:.2f} m2, silhouette {:.2f} m2, STAR {:.3f}\n",
        c["clusters"].get<std::size_t>(), c["leaf_area_m2"].get<double>(),
        c["sunlit_leaf_area_m2"].get<double>(), c["shaded_leaf_area_m2"].get<double>(),
        c["silhouette_area_m2"].get<double>(), c["star"].get<double>());
  }
  if (j.contains("canopy_light")) {
    const auto& c = j["canopy_light"];
    std::cout << fmt::format(
        "  canopy light ({} sky): sunlit {:.2f} m2, shaded {:.2f} m2, LIE {:.3f}, STAR {:.3f}",
        c["sky"].get<std::string>() == "site" ? "real" : "cos2",
        c["sunlit_leaf_area_m2"].get<double>(), c["shaded_leaf_area_m2"].get<double>(),
        c["lie"].get<double>(), c["star"].get<double>());
    if (c.contains("absorbed_par_mol_day")) {
      std::cout << fmt::format(", absorbed PAR {:.1f} mol/day",
                               c["absorbed_par_mol_day"].get<double>());
    }
    std::cout << '\n';
  }
}

// Only Newick carries node names (taxon names, quoted labels); converting to another format says
// how many are left behind rather than dropping them silently.
void warn_of_dropped_names(const NamedTree& named, const ConvertOptions& o) {
  if (tree_format_keeps_names(tree_format_for(o.out, o.to))) return;
  const auto named_nodes = std::count_if(named.names.begin(), named.names.end(),
                                         [](const std::string& n) { return !n.empty(); });
  if (named_nodes == 0) return;
  spdlog::warn("{}: {} node names are not kept in {}: only Newick (.nwk) carries names", o.in,
               named_nodes, o.out);
}

// Where a converted tree came from, and in which units an MTG was read.
std::string source_comment(const ConvertOptions& o, bool mesh) {
  std::string comment = "converted by fspm from " + std::filesystem::path(o.in).filename().string();
  if (!mesh && tree_format_for(o.in, o.from) == TreeFormat::kMtg) {
    const MtgTreeOptions m = default_mtg_tree_options();
    comment += fmt::format("; MTG lengths read in {}, diameters in {}, written in m",
                           length_unit_name(m.length_unit),
                           length_unit_name(m.diameter_unit.value_or(m.length_unit)));
  }
  return comment;
}

// The skeleton of a mesh: tubes of vertex rings, or one group of cross-sections per branch.
TreeGraph mesh_skeleton_of(const ConvertOptions& o) {
  std::size_t not_tubes = 0;
  TreeGraph t = scans::grouped_mesh_skeleton(scans::read_mesh_file(o.in, o.from), o.in, &not_tubes);
  if (not_tubes > 0) {
    spdlog::warn(
        "{}: {} mesh pieces are no tube of vertex rings (leaves, flat polygons) and are left "
        "out of the skeleton; remove them from the mesh if they are branches",
        o.in, not_tubes);
  }
  return t;
}

void run_convert(const ConvertOptions& o) {
  refuse_overwriting_input(o.out, {o.in});
  // A mesh of branch tubes, or one group (OBJ group or glTF node) per branch, gives its skeleton
  // (Reynolds et al. 2011, 3.1).
  const bool mesh = o.from == "obj" || o.from == "gltf" || o.from == "glb" || o.from == "ply" ||
                    (o.from.empty() && scans::is_mesh_file(o.in));
  const NamedTree named =
      mesh ? NamedTree{mesh_skeleton_of(o), {}} : read_named_tree_file(o.in, o.from);
  write_named_tree_file(named, o.out, o.to, source_comment(o, mesh));
  warn_of_dropped_names(named, o);
  spdlog::info("wrote {} ({} nodes)", o.out, named.tree.size());
}

}  // namespace

void add_tree_commands(CLI::App& app) {
  CLI::App* tree = app.add_subcommand("tree", "Inspect and convert tree graph files");
  tree->require_subcommand(1);
  const std::string formats = kTreeFormats;

  auto info = std::make_shared<InfoOptions>();
  CLI::App* i = tree->add_subcommand("info", "Print the summary of a tree file");
  i->add_option("FILE", info->file, "Tree file (.tree, .treeb, .nwk, .mtg)")->required();
  add_input_format_option(i, info->format);
  i->add_flag("--json", info->json, "Machine-readable JSON on stdout");
  i->add_option("--sky", info->sky_file,
                "TOML file with a real sky (sky = { site = {latitude, longitude, elevation}, "
                "date, hours | days }): the canopy light's sunlit area and absorbed PAR under it");
  i->callback([info] { run_info(*info); });

  auto conv = std::make_shared<ConvertOptions>();
  CLI::App* c = tree->add_subcommand("convert", "Convert a tree file to another format");
  c->add_option("IN", conv->in,
                "Input tree file (.tree, .treeb, .nwk, .mtg), or a mesh of branch tubes (.obj, "
                ".ply, .gltf, .glb) or with one group per branch (its skeleton)")
      ->required();
  c->add_option("OUT", conv->out, "Output tree file (.tree, .treeb, .nwk, .mtg)")->required();
  c->add_option("--from", conv->from, "Input format: " + formats + ", or obj, ply, gltf, glb");
  c->add_option("--format,--to", conv->to, "Output format: " + formats);
  c->callback([conv] { run_reporting_command([&] { run_convert(*conv); }); });
}

}  // namespace fspm::cli
