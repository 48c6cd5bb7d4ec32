// fspm encode | scan: trees from scans and meshes (Pirk sec. 3.3): a point set or tree model
// encoded into the cluster-based representation, and simulated scans of known trees.
#include <spdlog/fmt/fmt.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>

#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/tree_file.hpp"
#include "scans/clusters_file.hpp"
#include "scans/cylinders_csv.hpp"
#include "scans/encoder.hpp"
#include "scans/point_set_file.hpp"
#include "scans/point_set_writer.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/scanned_tree.hpp"
#include "scans/tree_measurements.hpp"

namespace fspm::cli {
namespace {

struct EncodeCommand {
  std::string input;
  std::string output;
  std::string species = "default";
  // Over the species' values (Table 3.1).
  std::optional<double> beta, gamma, f_s;
  // The options bound straight into the encoder's options, whose defaults are the options'.
  scans::EncodeOptions encode;
  std::string skeleton;
  std::string cylinders;
  std::string branch_skeleton;
  bool pirk_split = false;  // the inverse of encode.follow_main_axes
  std::uint64_t seed = 1;
  bool json = false;
};

bool is_tree_file(const std::string& path) { return is_tree_kind(file_kind_by_extension(path)); }

// A point set, or a tree model scanned as a laser scanner at four positions would see it.
scans::PointSet load_input(const EncodeCommand& o) {
  if (!is_tree_file(o.input)) return scans::read_point_set(o.input);
  std::mt19937_64 rng(o.seed);
  return scans::simulate_scan(read_tree_file(o.input), scans::ScanOptions{}, rng);
}

nlohmann::json optional_json(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

nlohmann::json measurements_json(const scans::TreeMeasurements& m) {
  return {{"dbh_m", optional_json(m.dbh_m)},
          {"height_m", m.height_m},
          {"crown_width_m", m.crown_width_m},
          {"crown_base_m", optional_json(m.crown_base_m)},
          {"woody_volume_m3", m.woody_volume_m3},
          {"branches_per_order", m.branches_per_order},
          {"branch_length_per_order_m", m.branch_length_per_order_m},
          {"points_explained_fraction", m.points_explained_fraction},
          {"breast_height_points", m.breast_height_points},
          {"stems", m.stems},
          {"breast_height_stems_m", m.breast_height_stems_m},
          {"cylinders", m.cylinders.size()},
          {"warnings", m.warnings}};
}

// Occlusion gaps the neighbour graph bridged, where (the middle of each bridge, in the input's
// coordinates) and how long: the skeleton there rests on a guess.
nlohmann::json gaps_json(const scans::EncodeResult& r) {
  nlohmann::json out = nlohmann::json::array();
  for (const scans::BridgedGap& g : r.gaps) {
    out.push_back({{"from", {g.from.x(), g.from.y(), g.from.z()}},
                   {"to", {g.to.x(), g.to.y(), g.to.z()}},
                   {"length_m", g.length_m}});
  }
  return out;
}

void run_encode(const EncodeCommand& o) {
  // The file is always the binary cluster format: another extension would misname it.
  if (file_kind_by_extension(o.output) != FileKind::kClusters) {
    throw ValueError("-o: encode writes the cluster format, expected a .clusters file", o.output);
  }
  refuse_overwriting_input(o.output, {o.input});
  refuse_overwriting_input(o.skeleton, {o.input});
  refuse_overwriting_input(o.cylinders, {o.input});
  refuse_overwriting_input(o.branch_skeleton, {o.input});
  const std::pair<const std::string&, const char*> outputs[] = {
      {o.output, "-o"},
      {o.skeleton, "--skeleton"},
      {o.cylinders, "--cylinders"},
      {o.branch_skeleton, "--branch-skeleton"}};
  for (std::size_t i = 0; i < std::size(outputs); ++i) {
    for (std::size_t j = i + 1; j < std::size(outputs); ++j) {
      refuse_same_output(outputs[i].first, outputs[i].second, outputs[j].first, outputs[j].second);
    }
  }
  scans::EncodeOptions options = o.encode;
  options.species = scans::species_by_name(o.species);
  if (o.beta) options.species.beta = *o.beta;
  if (o.gamma) options.species.gamma = *o.gamma;
  if (o.f_s) options.species.f_s = *o.f_s;
  options.follow_main_axes = !o.pirk_split;
  const scans::PointSet points = load_input(o);
  const auto t0 = std::chrono::steady_clock::now();
  scans::ScannedTree tree = [&] {
    try {
      return scans::encode_and_measure(points, options);
    } catch (const MemoryLimitError& e) {
      if (!e.file().empty()) throw;
      throw MemoryLimitError(e.message(), o.input);  // which input was too large
    } catch (const ValueError& e) {
      if (!e.file().empty()) throw;
      throw ValueError(e.message(), o.input);  // "no trunk diameter could be fitted": in which
    }
  }();
  const scans::EncodeResult& r = tree.encoding;
  const scans::TreeMeasurements& m = tree.measurements;
  const std::string bytes = scans::clusters_bytes(r.model);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const std::string& w : m.warnings) spdlog::warn("{}: {}", o.input, w);
  nlohmann::json doc = {{"points", r.points},
                        {"skeleton_nodes", r.model.skeleton.size()},
                        {"clusters", r.model.clusters.size()},
                        {"bytes", bytes.size()},
                        {"seconds", seconds},
                        {"root_diameter_m", r.model.root_diameter_m},
                        {"species", r.model.species},
                        {"beta", r.model.beta},
                        {"gamma", r.model.gamma},
                        {"f_s", r.model.f_s},
                        {"bridges", r.bridges},
                        {"gaps", gaps_json(r)},
                        {"ground_points", r.ground_points},
                        {"isolated_points", tree.isolated_points},
                        {"branch_skeleton_nodes", r.branch_skeleton.size()},
                        {"origin", {r.origin.x(), r.origin.y(), r.origin.z()}},
                        {"output", o.output}};
  doc.update(measurements_json(m));
  if (!m.tree_found) {
    if (o.json) print_json(doc);
    throw ValueError("no tree found (" + m.warnings.front() + "); nothing written", o.input);
  }
  scans::write_clusters_file(r.model, o.output);
  if (!o.skeleton.empty()) write_tree_file(r.model.skeleton, o.skeleton);
  if (!o.cylinders.empty()) scans::write_cylinders_csv(m.cylinders, o.cylinders);
  if (!o.branch_skeleton.empty()) write_tree_file(r.branch_skeleton, o.branch_skeleton);
  spdlog::info("{}: {} points -> {} skeleton nodes, {} clusters, {} bytes -> {}", o.input, r.points,
               r.model.skeleton.size(), r.model.clusters.size(), bytes.size(), o.output);
  if (o.json) print_json(doc);
}

void add_encode_command(CLI::App& app) {
  auto o = std::make_shared<EncodeCommand>();
  CLI::App* e = app.add_subcommand(
      "encode",
      "Cluster-based representation of a scanned tree (Pirk sec. 3.3): skeleton, radii, "
      "leaf clusters");
  e->add_option("INPUT", o->input,
                "Point set (.ply, .xyz, .txt, .csv, .pcd, .las), mesh (.obj, .gltf, .glb: its "
                "vertices) or tree model (.tree, .treeb, .nwk, .mtg: scanned from four positions "
                "first)")
      ->required();
  e->add_option("-o,--output", o->output, "The .clusters file to write")->required();
  e->add_option("--species", o->species, "Parameters of Pirk Table 3.1 (pine, willow, ...)");
  e->add_option("--beta", o->beta, "Edge weight exponent |u-v|^beta")->check(positive_number(10));
  e->add_option("--gamma", o->gamma, "Allometric exponent of eq. 3.1")->check(number_in(0, 10));
  e->add_option("--fs", o->f_s, "Cluster factor f_s of eq. 3.2")->check(positive_number(10));
  e->add_option("--root-diameter", o->encode.root_diameter_m,
                "Trunk diameter d_root in m (default: fitted to the trunk points)")
      ->check(positive_number(100));
  e->add_option("--bin-length", o->encode.bin_length_m,
                "Skeleton node spacing in m (default: 1/40 "
                "of the longest path)")
      ->check(positive_number(1000));
  e->add_option("--neighbours", o->encode.neighbours, "k of the neighbour graph")
      ->check(number_in(1, 64))
      ->capture_default_str();
  e->add_option("--skeleton", o->skeleton, "Also write the main skeleton as a tree file");
  e->add_option("--cylinders", o->cylinders,
                "Also write the fitted cylinders as CSV with TreeQSM's columns (start, axis, "
                "length, radius, parent, branch, order)");
  e->add_option("--branch-skeleton", o->branch_skeleton,
                "Also write the skeleton of every branch the scan shows (before the cluster "
                "split of eq. 3.2, short side tips removed) as a tree file");
  e->add_flag("--keep-ground", o->encode.keep_ground,
              "Keep points near the cloud's lower envelope (default: removed as ground)");
  e->add_flag("--pirk-split", o->pirk_split,
              "Main skeleton by eq. 3.2 alone, as Pirk (default: the trunk to the top and the "
              "main limbs to their tips, eq. 3.2 for the smaller branches)");
  e->add_option("--main-branch-share", o->encode.main_branch_share,
                "Share of the skeleton's length a limb must carry to stay in the main skeleton "
                "without passing eq. 3.2")
      ->check(number_in(0, 1))
      ->capture_default_str();
  e->add_option("--main-branch-reach", o->encode.main_branch_reach,
                "Share of the skeleton's longest path a limb must reach beyond its fork to stay "
                "in the main skeleton without passing eq. 3.2 (0: off)")
      ->check(number_in(0, 1))
      ->capture_default_str();
  e->add_option("--seed", o->seed, "Seed of the simulated scan of a tree model")
      ->check(number_in(0, kMaxSeed));
  e->add_flag("--json", o->json,
              "One JSON object on stdout: points, skeleton_nodes, clusters, bytes, seconds, "
              "and the measurements (dbh_m, height_m, crown_width_m, crown_base_m, "
              "woody_volume_m3, ..., warnings)");
  e->callback([o] { run_reporting_command([&] { run_encode(*o); }); });
}

struct ScanCommand {
  std::string tree;
  std::string output;
  // The options bound straight into the simulator's options, whose defaults are the options'.
  scans::ScanOptions options;
  double noise_mm = options.range_noise_m * 1000.0;  // the range noise in mm
  std::uint64_t seed = 1;
  bool json = false;
};

void run_scan(const ScanCommand& o) {
  refuse_overwriting_input(o.output, {o.tree});
  scans::ScanOptions options = o.options;
  options.range_noise_m = o.noise_mm / 1000.0;
  std::mt19937_64 rng(o.seed);
  const scans::PointSet points = scans::simulate_scan(read_tree_file(o.tree), options, rng);
  scans::write_point_set(points, o.output);
  spdlog::info("{}: {} points from {} scanner positions -> {}", o.tree, points.points.size(),
               options.scanners, o.output);
  if (o.json) print_json({{"points", points.points.size()}, {"output", o.output}});
}

void add_scan_command(CLI::App& app) {
  auto o = std::make_shared<ScanCommand>();
  CLI::App* s = app.add_subcommand(
      "scan", "Simulated laser scan of a tree model: visible branch surfaces, range noise");
  s->add_option("TREE", o->tree, "The tree (.tree, .treeb, .nwk, .mtg)")->required();
  s->add_option("-o,--output", o->output, "Point set to write (.ply or .xyz)")->required();
  s->add_option("--scanners", o->options.scanners, "Scanner positions around the tree")
      ->check(number_in(1, 64))
      ->capture_default_str();
  s->add_option("--density", o->options.density_per_m2,
                "Points per m^2 at the scanner distance and normal incidence")
      ->check(positive_number(1e8))
      ->capture_default_str();
  s->add_option("--noise-mm", o->noise_mm, "Standard deviation of the range error in mm")
      ->check(number_in(0, 1000))
      ->capture_default_str();
  s->add_option("--min-radius", o->options.min_radius_m,
                "Internodes thinner than this (m) are "
                "not scanned")
      ->check(number_in(0, 100))
      ->capture_default_str();
  s->add_option("--seed", o->seed, "Seed of the random generator")->check(number_in(0, kMaxSeed));
  s->add_flag("--json", o->json, "One JSON object on stdout: points, output");
  s->callback([o] { run_reporting_command([&] { run_scan(*o); }); });
}

}  // namespace

void add_scan_commands(CLI::App& app) {
  add_encode_command(app);
  add_scan_command(app);
}

}  // namespace fspm::cli
