// fspm decode: a cluster-based tree (.clusters, Pirk sec. 3.3) decoded into a tree (Pirk sec. 3.4):
// the skeleton and its clusters textured with patches of the species library, written as a tree
// file or as a mesh (.glb keeps each patch once and places it by instances), optionally with the
// patch leaves stochastically pruned for a viewer at a distance (Pirk sec. 3.5.2).
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <Eigen/Geometry>
#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/commands.hpp"
#include "cli/full_command_list.hpp"
#include "cli/lsystem_source.hpp"
#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/mesh_writers.hpp"
#include "scan_decoding/decoding.hpp"
#include "scans/clusters_file.hpp"

namespace fspm::cli {
namespace {

struct DecodeCommand {
  std::string input;
  std::string output;
  // The options bound straight into the decoder's options, whose defaults are the options'.
  scan_decoding::DecodeOptions decode;
  scan_decoding::DecodeMeshOptions mesh;
  std::optional<double> lod_distance_m;
  bool docking_only = false;  // the inverse of decode.texture.match_branch_length
  bool json = false;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The camera of --lod: `distance_m` in front (-y) of the centre of the skeleton and hulls.
Eigen::Vector3d lod_camera(const scans::ClusterModel& model, double distance_m) {
  Eigen::AlignedBox3d box;
  for (NodeId n = 0; n < model.skeleton.size(); ++n) {
    box.extend(model.skeleton.start(n));
    box.extend(model.skeleton.end(n));
  }
  for (const scans::ClusterHull& h : model.clusters) {
    for (const Eigen::Vector3d& v : h.vertices) box.extend(v);
  }
  return box.center() - distance_m * Eigen::Vector3d::UnitY();
}

double scanned_branch_length_m(const scans::ClusterModel& model) {
  double sum = 0.0;
  for (const scans::ClusterHull& h : model.clusters) sum += h.branch_length_m;
  return sum;
}

void run_decode(const DecodeCommand& o) {
  refuse_overwriting_input(o.output, {o.input});
  const bool mesh_output = is_mesh_path(o.output);
  if (!mesh_output) (void)tree_format_for(o.output);  // ValueError naming the formats
  if (o.lod_distance_m && !mesh_output) {
    throw ValueError("--lod prunes the leaves of a mesh: write .glb, .obj, .ply or .vtp", o.output);
  }
  const scans::ClusterModel model = scans::read_clusters_file(o.input);
  const auto t0 = std::chrono::steady_clock::now();
  scan_decoding::DecodeOptions options = o.decode;
  options.texture.match_branch_length = !o.docking_only;
  const scan_decoding::Decoding decoding = scan_decoding::decode_clusters(model, options);
  nlohmann::json summary{{"clusters", model.clusters.size()},
                         {"library_patches", decoding.library.patches.size()},
                         {"instances", decoding.placements.size()},
                         {"species", decoding.library.species},
                         {"branch_length_m", scan_decoding::textured_branch_length_m(decoding)},
                         {"scanned_branch_length_m", scanned_branch_length_m(model)}};
  const TreeGraph tree = scan_decoding::decoded_tree(model, decoding);
  summary["nodes"] = tree.size();
  if (mesh_output) {
    scan_decoding::DecodeMeshOptions mesh_options = o.mesh;
    mesh_options.seed = options.seed;  // --seed orders the leaves too
    if (o.lod_distance_m) mesh_options.camera_m = lod_camera(model, *o.lod_distance_m);
    const graphics::InstancedMesh mesh = scan_decoding::decoded_mesh(model, decoding, mesh_options);
    summary["seconds"] = seconds_since(t0);
    summary["triangles"] = mesh.triangle_count();
    summary["stored_triangles"] = mesh.stored_triangle_count();
    summary["meshes"] = mesh.meshes.size();
    graphics::write_mesh(mesh, o.output);
  } else {
    summary["seconds"] = seconds_since(t0);
    summary["triangles"] = 0;
    write_tree_file(tree, o.output);
  }
  summary["output"] = o.output;
  spdlog::info("{}: {} clusters textured with {} patch instances -> {} nodes -> {}", o.input,
               model.clusters.size(), decoding.placements.size(), tree.size(), o.output);
  if (o.json) print_json(summary);
}

}  // namespace

void add_decode_commands(CLI::App& app) {
  auto o = std::make_shared<DecodeCommand>();
  CLI::App* d = app.add_subcommand(kDecodeCommand.name, kDecodeCommand.description);
  d->add_option("MODEL", o->input, "Cluster-based tree (.clusters, from fspm encode)")->required();
  d->add_option("-o,--output", o->output,
                "Tree file (.tree, .treeb, .nwk, .mtg) or mesh (.glb with each patch stored once, "
                ".obj, .ply, .vtp)")
      ->required();
  d->add_option("--species", o->decode.species,
                "Species library to texture with (Pirk Table 3.1 names; default: the model's)");
  d->add_option("--branchlets", o->decode.library.branchlets,
                "L-system branchlets in the species library")
      ->check(number_in(1, 1000))
      ->capture_default_str();
  d->add_option("--lod", o->lod_distance_m,
                "Mesh seen from this distance in m (in front of the tree): each patch draws a "
                "prefix of its randomly ordered leaves, enlarged (stochastic pruning)")
      ->check(positive_number(1e9));
  d->add_option("--prune-distance", o->mesh.prune_distance_m,
                "With --lod: every leaf is drawn up to this distance in m, beyond it the share "
                "(prune distance / distance)^2")
      ->check(positive_number(1e9))
      ->capture_default_str();
  d->add_option("--seed", o->decode.seed, "Seed of the patch choice, roll and leaf order")
      ->check(number_in(0, kMaxSeed))
      ->capture_default_str();
  d->add_flag("--docking-only", o->docking_only,
              "Texture each cluster only until its docking points are used up (Pirk 3.4), not on "
              "to the branch length the scan showed in it");
  d->add_flag("--json", o->json,
              "One JSON object on stdout: nodes, triangles, instances, branch_length_m, "
              "scanned_branch_length_m, seconds, ...");
  d->callback([o] { run_reporting_command([&] { run_decode(*o); }); });
}

}  // namespace fspm::cli
