#pragma once
// What the graphics commands (mesh, render, view) share: the options they declare alike, the
// checks of inputs they refuse alike, and the crowns drawn by ray casting.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/graph_lod_option.hpp"
#include "cli/lsystem_source.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"

namespace fspm::cli {

// --leaves that finds no leaf, polygon or leaf cluster says so instead of drawing nothing quietly.
void report_missing_leaves(const graphics::InstancedMesh& mesh, const std::string& file);

// Meshes, instances, stored triangles and bounds for --json.
nlohmann::json instancing_json(const graphics::InstancedMesh& m);

// An L-system (.l) drawn for render, mesh and view: explicitly, or by instancing with
// --compressed. `pixels` > 0 (pictures): substructures smaller than a pixel of a picture that many
// pixels across drawn as their chord; 0: every substructure exact.
LsystemDrawing draw_lsystem_file(const std::string& file, const LsystemDrawArguments& arguments,
                                 int pixels);

// --max-order and --merge-collinear reduce trees and compressed plants (in scenes too); an
// L-system is written as a plant first, and the per-plant --lod meshes every plant whole.
void check_graph_lod(const GraphLodArguments& arguments, const std::vector<std::string>& files,
                     bool per_plant_lod);

// --axis-subdivisions S of mesh, render and view (MeshOptions::axis_subdivisions).
void add_axis_subdivisions_option(CLI::App* app, graphics::MeshOptions& options);
// --leaves, --foliage and --seed of the commands that draw leaves and leaf clusters, bound into
// the mesh options (their defaults are the options').
void add_leaves_options(CLI::App* command, graphics::MeshOptions& options,
                        const std::string& leaves_help);
// --lod and --lod-distance of render and view.
void add_lod_options(CLI::App* command, bool& lod, double& distance_m);
// --ray-cast of render and view.
void add_ray_cast_flag(CLI::App* command, bool& ray_cast);

// What --ray-cast draws for one crown file from fspm crown or one scene: the crowns, drawn by
// relief-mapped ray casting of their cubemaps (Argudo 5.1), and everything else as meshes (the
// crowns' trunks, the scene's other plants, obstacles and terrain).
struct RayCastInput {
  std::vector<graphics::ReliefCrown> crowns;
  graphics::InstancedMesh meshes;
};
RayCastInput load_ray_cast_input(const std::vector<std::string>& paths,
                                 const graphics::MeshOptions& mesh_options);

// The commands, each in its own file.
void add_mesh_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_view_command(CLI::App& app);

}  // namespace fspm::cli
