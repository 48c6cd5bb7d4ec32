// fspm greenlab simulate | reconstruct | fit: GreenLab plants from TOML descriptions, compressed
// tree graphs (.ctree), reconstruction at any age and GL1 calibration.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/graph_lod_option.hpp"
#include "cli/output.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/compressed_tree_graph.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/line_tree.hpp"
#include "fspm/tree_file.hpp"
#include "greenlab/calibration.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/simulation.hpp"

namespace fspm::cli {
namespace {

struct SimulateOptions {
  std::string params;
  std::string out;
  int cycles = -1;
  std::int64_t seed = -1;
  bool json = false;
};

struct ReconstructOptions {
  std::string graph;
  std::string out;
  std::string format;
  double age = -1.0;
  bool no_leaves = false;
  GraphLodArguments lod;
  bool json = false;
};

struct FitOptions {
  std::string params;
  std::string targets;
  std::string out;
  greenlab::FitOptions fit;  // --max-iterations bound into it, its default the option's
  bool json = false;
};

void run_simulate(const SimulateOptions& o) {
  refuse_overwriting_input(o.out, {o.params});
  greenlab::PlantParams params = greenlab::read_plant_params(o.params);
  if (o.cycles >= 0) params.cycles = o.cycles;
  if (o.seed >= 0) params.seed = static_cast<std::uint64_t>(o.seed);
  const auto t0 = std::chrono::steady_clock::now();
  const CompressedTreeGraph g = greenlab::simulate_compressed(params);
  const double seconds = seconds_since(t0);
  write_ctree_file(g, o.out);
  const auto bytes = std::filesystem::file_size(written_file(o.out));
  const greenlab::OrganCounts c = greenlab::count_organs(g);
  nlohmann::json by_age = nlohmann::json::object();
  for (const auto& [age, n] : c.metamers_by_age) by_age[std::to_string(age)] = n;
  // Jaeger's Table 1: the line tree of every age 1..final, and their sum (the sequence size).
  nlohmann::json line_bytes = nlohmann::json::object();
  std::uint64_t sequence_bytes = 0;
  for (int age = 1; age <= static_cast<int>(g.final_age); ++age) {
    greenlab::ReconstructionOptions ro;
    ro.age = age;
    const std::uint64_t age_bytes = greenlab::line_records_at_age(g, ro) *
                                    static_cast<std::uint64_t>(LineTree::kBytesPerRecord);
    line_bytes[std::to_string(age)] = age_bytes;
    sequence_bytes += age_bytes;
  }
  const nlohmann::json j = {{"cycles", params.cycles},
                            {"graph_nodes", g.size()},
                            {"metamers", c.metamers},
                            {"leaves", c.leaves},
                            {"flowers", c.flowers},
                            {"buds", c.buds},
                            {"graph_bytes", bytes},
                            {"metamers_by_age", by_age},
                            {"line_tree_bytes_by_age", line_bytes},
                            {"sequence_bytes", sequence_bytes},
                            {"seconds", seconds},
                            {"output", o.out}};
  if (o.json) {
    print_json(j);
    return;
  }
  spdlog::info("wrote {} ({} node records for {} metamers, {} bytes)", o.out, g.size(), c.metamers,
               bytes);
}

void run_reconstruct(const ReconstructOptions& o) {
  refuse_overwriting_input(o.out, {o.graph});
  const CompressedTreeGraph g = read_ctree_file(o.graph);
  greenlab::ReconstructionOptions ro;
  ro.age = o.age;
  ro.leaves = !o.no_leaves;
  ro.lod = o.lod.lod();
  greenlab::ReconstructionStats st;
  const auto t0 = std::chrono::steady_clock::now();
  const TreeGraph tree = greenlab::reconstruct(g, ro, &st);
  const double seconds = seconds_since(t0);
  write_tree_file(tree, o.out, o.format);
  const nlohmann::json j = {{"age", st.age},
                            {"metamers", st.metamers},
                            {"leaves", st.leaves},
                            {"flowers", st.flowers},
                            {"pruned_axes", st.pruned_axes},
                            {"components", st.components()},
                            {"nodes", tree.size()},
                            {"seconds", seconds},
                            {"output", o.out}};
  if (o.json) {
    print_json(j);
    return;
  }
  spdlog::info("wrote {} at age {} ({} metamers, {} components, {:.3f} s)", o.out, st.age,
               st.metamers, st.components(), seconds);
}

void run_fit(const FitOptions& o) {
  refuse_overwriting_input(o.out, {o.params, o.targets});
  const std::string text = read_input_file(o.params);
  const greenlab::PlantParams params = greenlab::parse_plant_params(text, o.params);
  const auto targets = greenlab::read_targets_csv(o.targets);
  const greenlab::FitResult fit = greenlab::fit_gl1(params, targets, {}, o.fit);
  const std::string toml = greenlab::fitted_toml(text, fit, o.params);
  write_file_atomically(o.out, [&](std::ostream& out) { out << toml; });
  nlohmann::json parameters = nlohmann::json::array();
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    const double se = fit.standard_errors[i];
    parameters.push_back(
        {{"name", fit.names[i]},
         {"initial", fit.initial[i]},
         {"estimate", fit.estimates[i]},
         {"std_error", std::isfinite(se) ? nlohmann::json(se) : nlohmann::json()}});
  }
  const nlohmann::json j = {{"parameters", parameters},   {"initial_cost", fit.initial_cost},
                            {"cost", fit.final_cost},     {"iterations", fit.iterations},
                            {"converged", fit.converged}, {"targets", targets.size()},
                            {"residuals", fit.residuals}, {"output", o.out}};
  if (o.json) {
    print_json(j);
    return;
  }
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    std::cout << fit.names[i] << " = " << fit.estimates[i] << " +- " << fit.standard_errors[i]
              << '\n';
  }
  std::cout << "cost " << fit.final_cost << " (initial " << fit.initial_cost << ") after "
            << fit.iterations << " iterations\n";
}

}  // namespace

void add_greenlab_commands(CLI::App& app) {
  CLI::App* gl = app.add_subcommand("greenlab", "GreenLab plants: simulate, reconstruct, fit");
  gl->require_subcommand(1);

  auto sim = std::make_shared<SimulateOptions>();
  CLI::App* s = gl->add_subcommand(
      "simulate", "Simulate a plant description into a compressed tree graph (.ctree)");
  s->add_option("PARAMS", sim->params, "Plant description (TOML)")->required();
  s->add_option("--cycles", sim->cycles, "Growth cycles (default: plant.cycles)")
      ->check(number_in(0, greenlab::kMaxCycles));
  s->add_option("--seed", sim->seed, "Random seed for GL2 plants (default: plant.seed)")
      ->check(number_in(0, kMaxSeed));
  s->add_option("-o,--output", sim->out, "Output .ctree file")->required();
  s->add_flag("--json", sim->json, "Machine-readable JSON on stdout");
  s->callback([sim] { run_reporting_command([&] { run_simulate(*sim); }); });

  auto rec = std::make_shared<ReconstructOptions>();
  CLI::App* r = gl->add_subcommand(
      "reconstruct", "Rebuild the explicit tree at any age from a compressed tree graph");
  r->add_option("PLANT", rec->graph, "Compressed tree graph (.ctree)")->required();
  r->add_option("--age", rec->age, "Plant age in cycles (default: the simulated age)")
      ->check(number_in(0, greenlab::kMaxCycles));
  r->add_option("-o,--output", rec->out, "Output tree file (.tree, .treeb, .nwk, .mtg)")
      ->required();
  r->add_option("--format", rec->format, "Output format (default: from the extension)");
  r->add_flag("--no-leaves", rec->no_leaves, "Leave the leaves out");
  add_graph_lod_options(r, rec->lod);
  r->add_flag("--json", rec->json, "Machine-readable JSON on stdout");
  r->callback([rec] { run_reporting_command([&] { run_reconstruct(*rec); }); });

  auto fit = std::make_shared<FitOptions>();
  CLI::App* f = gl->add_subcommand(
      "fit", "Calibrate GL1 parameters on target data (CSV: quantity,age,cycle,value)");
  f->add_option("PARAMS", fit->params,
                "Plant description (TOML) with [functional] and [calibration]")
      ->required();
  f->add_option("TARGET", fit->targets, "Target data (CSV, see docs/greenlab.md)")->required();
  f->add_option("-o,--output", fit->out, "Fitted plant description (TOML)")->required();
  f->add_option("--max-iterations", fit->fit.max_iterations, "Solver iteration limit")
      ->check(number_in(1, 1e6))
      ->capture_default_str();
  f->add_flag("--json", fit->json, "Machine-readable JSON on stdout");
  f->callback([fit] { run_reporting_command([&] { run_fit(*fit); }); });
}

}  // namespace fspm::cli
