// fspm lsystem derive | interpret: run cpfg / ABOP L-system files.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/lsystem_source.hpp"
#include "cli/output.hpp"
#include "fspm/count_json.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_tree.hpp"
#include "fspm/number_text.hpp"
#include "fspm/saturating.hpp"
#include "fspm/tree_file.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/substructure_derivation.hpp"
#include "lsystem/turtle.hpp"

namespace fspm::cli {
namespace {

struct LsystemOptions : LsystemSource {
  bool string = false;
  bool json = false;
  bool compressed = false;
  double detail = 0.0;
  std::string output;
  std::string format;
};

void add_common(CLI::App* cmd, LsystemOptions& o) {
  cmd->add_option("file", o.file, "L-system file (.l, cpfg syntax)")->required();
  cmd->add_option("--steps", o.steps, "Derivation steps (overrides 'derivation length:')")
      ->check(number_in(0, lsystem::kMaxDerivationLength));
  cmd->add_option("--seed", o.seed, "Seed of ran() and stochastic productions")
      ->check(number_in(0, kMaxSeed));
  cmd->add_option("--define", o.defines, "Override a #define: NAME=VALUE (repeatable)");
  cmd->add_option("--budget", o.budget, "Largest string allowed, in modules")
      ->check(number_in(1, 1e15));
  cmd->add_option("--variants", o.variants,
                  "With --compressed: derive stochastic L-systems into substructures, each in at "
                  "most K variants drawn from the seeded generator (Jaeger 2.1.3)")
      ->check(number_in(1, 1e6));
}

nlohmann::json symbol_counts(const std::vector<std::uint64_t>& per_symbol,
                             const lsystem::SymbolTable& table) {
  nlohmann::json symbols = nlohmann::json::object();
  for (std::size_t i = 0; i < per_symbol.size(); ++i) {
    if (per_symbol[i]) {
      symbols[table.name(static_cast<lsystem::SymbolId>(i))] = count_json(per_symbol[i]);
    }
  }
  return symbols;
}

// -o OUT.ctree: the derived plant drawn by the turtle (by instancing with --compressed) and
// written as a compressed tree graph with turtle geometry; the summary gains its size.
void write_derive_output(const LsystemOptions& o, nlohmann::json& summary) {
  if (o.output.empty()) return;
  const LsystemDrawing drawing = draw_lsystem(o, o.compressed, 0.0, 0);
  write_lsystem_ctree(drawing, o.output, summary);
  summary["output"] = o.output;
  spdlog::info("{}: wrote {} ({} records, {} bytes)", o.file, o.output,
               json_text(summary["ctree_records"]), json_text(summary["ctree_bytes"]));
}

// --compressed: the string as a graph of shared substructures (Jaeger 2.1.3), its module counts
// computed on the graph.
void run_derive_compressed(const LsystemOptions& o, const lsystem::LSystem& sys) {
  const auto t0 = std::chrono::steady_clock::now();
  const lsystem::SubstructureGraph g =
      lsystem::derive_substructures(sys, derive_options(o), o.variants);
  const lsystem::SubstructureCounts c = lsystem::count_modules(g, sys.symbols.size());
  const double seconds = seconds_since(t0);
  const std::size_t graph_bytes = g.memory_bytes();
  const double compression = static_cast<double>(c.explicit_bytes) /
                             static_cast<double>(std::max<std::size_t>(graph_bytes, 1));
  spdlog::info("{}: {} steps, {} modules as {} substructures ({} bytes) in {:.6f} s", o.file,
               g.steps, count_text(c.modules), g.nodes.size(), graph_bytes, seconds);
  const nlohmann::json symbols = symbol_counts(c.per_symbol, sys.symbols);
  // A saturated string size gives a lower bound of the compression, not its value.
  const nlohmann::json compression_json =
      c.explicit_bytes == kSaturated
          ? nlohmann::json("more than " + format_significant(compression))
          : nlohmann::json(compression);
  std::string text;
  if (o.string) text = lsystem::to_string(lsystem::expand(g, o.budget), sys.symbols);
  nlohmann::json written = nlohmann::json::object();
  write_derive_output(o, written);
  if (o.json) {
    nlohmann::json j = {{"steps", g.steps},
                        {"modules", count_json(c.modules)},
                        {"symbols", symbols},
                        {"compressed", true},
                        {"graph_nodes", g.nodes.size()},
                        {"graph_bytes", graph_bytes},
                        {"explicit_bytes", count_json(c.explicit_bytes)},
                        {"compression", compression_json},
                        {"seconds", seconds}};
    // Counts of 2^64 - 1 or more are given as "more than 10^19".
    if (c.saturated) j["counts_saturated"] = true;
    if (o.string) j["string"] = text;
    j.update(written);
    print_json(j);
    return;
  }
  if (o.string) {
    std::cout << text << '\n';
    return;
  }
  std::cout << "steps: " << g.steps << '\n' << "modules: " << count_text(c.modules) << '\n';
  std::cout << "symbols: " << json_text(symbols) << '\n';
  std::cout << "substructures: " << g.nodes.size() << " (" << graph_bytes << " bytes, "
            << (c.saturated ? "more than " : "") << compression
            << " times smaller than the string)\n";
}

void run_derive(const LsystemOptions& o) {
  if (!o.output.empty()) {
    if (!is_ctree_path(o.output)) {
      throw ValueError(
          "derive writes a compressed tree graph: use an output ending in .ctree "
          "(fspm lsystem interpret writes tree files and meshes)",
          o.output);
    }
    refuse_overwriting_input(o.output, {o.file, o.view});
  }
  const lsystem::LSystem sys = lsystem::parse_lsystem_file(o.file, parse_defines(o.defines));
  std::string why_not;
  if (o.compressed) {
    if (const auto obstacle = lsystem::factorization_obstacle(sys, o.variants > 0)) {
      why_not = "it has " + *obstacle;
      if (o.variants == 0 && !lsystem::factorization_obstacle(sys, true)) {
        why_not += " (--variants K derives it with K variants per substructure)";
      }
      // With -o the drawing warns the same (draw_lsystem): once is enough.
      if (o.output.empty()) {
        spdlog::warn("{}: derived explicitly, not into substructures: {}", o.file, why_not);
      }
    } else {
      run_derive_compressed(o, sys);
      return;
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  lsystem::Derivation d(sys, derive_options(o));
  d.run();
  const double seconds = seconds_since(t0);
  const lsystem::ModuleString& s = d.string();
  spdlog::info("{}: {} steps, {} modules in {:.3f} s", o.file, d.steps_done(), s.size(), seconds);
  std::vector<std::uint64_t> per_symbol(sys.symbols.size(), 0);
  for (lsystem::SymbolId id : s.symbols()) ++per_symbol[id];
  const nlohmann::json symbols = symbol_counts(per_symbol, sys.symbols);
  nlohmann::json written = nlohmann::json::object();
  write_derive_output(o, written);
  if (o.json) {
    nlohmann::json j = {{"steps", d.steps_done()}, {"modules", s.size()}, {"symbols", symbols}};
    if (o.compressed) {
      j["compressed"] = false;
      j["why_not_compressed"] = why_not;
    }
    if (o.string) j["string"] = lsystem::to_string(s, sys.symbols);
    j.update(written);
    print_json(j);
    return;
  }
  if (o.string) {
    std::cout << lsystem::to_string(s, sys.symbols) << '\n';
    return;
  }
  std::cout << "steps: " << d.steps_done() << '\n' << "modules: " << s.size() << '\n';
  std::cout << "symbols: " << json_text(symbols) << '\n';
}

// --compressed, or a mesh output: the drawing as prototypes and placements (one prototype when
// drawn explicitly), written as a mesh or expanded into a tree file.
void run_interpret_drawing(const LsystemOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  const LsystemDrawing drawing = draw_lsystem(o, o.compressed, o.detail, 0);
  nlohmann::json summary = drawing.summary;
  if (is_mesh_path(o.output)) {
    write_lsystem_mesh(drawing, o.output, summary);
  } else if (is_ctree_path(o.output)) {
    write_lsystem_ctree(drawing, o.output, summary);
  } else {
    const TreeGraph tree = expand_instanced_tree(drawing.tree, o.budget);
    if (tree.empty()) {
      throw ValueError("the derived string draws nothing (no F module): no tree to write", o.file);
    }
    write_tree_file(tree, o.output, o.format);
    summary["nodes"] = tree.size();
  }
  summary["output"] = o.output;
  summary["seconds"] = seconds_since(t0);
  spdlog::info("{}: {} steps, {} prototypes placed {} times -> {}", o.file,
               json_text(summary["steps"]), json_text(summary["prototypes"]),
               summary.contains("instances") ? human_text(summary["instances"]) : "1", o.output);
  if (o.json) print_json(summary);
}

void run_interpret(const LsystemOptions& o) {
  refuse_overwriting_input(o.output, {o.file, o.view});
  if (o.compressed || is_mesh_path(o.output) || is_ctree_path(o.output)) {
    run_interpret_drawing(o);
    return;
  }
  const lsystem::LSystem sys = lsystem::parse_lsystem_file(o.file, parse_defines(o.defines));
  const lsystem::TurtleSettings view =
      o.view.empty() ? lsystem::view_for_lsystem(o.file) : lsystem::read_view_file(o.view);
  lsystem::DeriveOptions options = derive_options(o);
  options.turtle = &view;
  lsystem::Derivation d(sys, options);
  d.run();
  const lsystem::Interpretation result =
      lsystem::interpret(d.interpretation_string(), sys.symbols, view);
  if (result.tree.empty()) {
    throw ValueError("the derived string draws nothing (no F module): no tree to write", o.file);
  }
  write_tree_file(result.tree, o.output, o.format);
  // Leaves: polygons { . } and predefined surfaces ~x alike (leaf nodes of the graph).
  std::size_t leaves = 0;
  for (NodeId n = 0; n < result.tree.size(); ++n) {
    leaves += result.tree.kind(n) == OrganKind::kLeaf ? 1 : 0;
  }
  spdlog::info("{}: {} steps, {} modules -> {} nodes ({} leaves) in {}", o.file, d.steps_done(),
               d.string().size(), result.tree.size(), leaves, o.output);
  if (o.json) {
    print_json({{"steps", d.steps_done()},
                {"modules", d.string().size()},
                {"nodes", result.tree.size()},
                {"leaves", leaves},
                {"polygons", result.leaves.size()},
                {"output", o.output}});
  }
}

}  // namespace

void add_lsystem_commands(CLI::App& app) {
  auto* group = app.add_subcommand("lsystem", "Derive and interpret L-systems (cpfg / ABOP)");
  group->require_subcommand(1);

  auto derive_opts = std::make_shared<LsystemOptions>();
  auto* derive = group->add_subcommand("derive", "Derive the string of an L-system file");
  add_common(derive, *derive_opts);
  derive->add_flag("--string", derive_opts->string, "Print the derived string (cpfg notation)");
  derive->add_flag("--json", derive_opts->json, "One JSON object: steps, modules, symbols");
  derive->add_flag("--compressed", derive_opts->compressed,
                   "Derive into shared substructures (context-free L-systems without ran() or "
                   "per-step blocks): counts of strings far too large to hold; --json adds "
                   "graph_nodes, graph_bytes, explicit_bytes and compression");
  derive->add_option("-o,--output", derive_opts->output,
                     "Write the derived plant, drawn by the turtle (by instancing with "
                     "--compressed), as a compressed tree graph with turtle geometry (.ctree) "
                     "for fspm greenlab reconstruct, mesh, render and view; --json adds "
                     "ctree_records, ctree_organs and ctree_bytes");
  derive->add_option("--view", derive_opts->view,
                     "With -o: view file (.v; default: the .v beside FILE)");
  derive->callback([derive_opts] { run_reporting_command([&] { run_derive(*derive_opts); }); });

  auto interp_opts = std::make_shared<LsystemOptions>();
  auto* interp = group->add_subcommand("interpret", "Derive and draw into a tree graph file");
  add_common(interp, *interp_opts);
  interp->add_option("--view", interp_opts->view, "View file (.v; default: the .v beside FILE)");
  interp
      ->add_option("-o,--output", interp_opts->output,
                   "Tree file (.tree, .treeb, .nwk, .mtg), mesh (.glb keeps the instances; "
                   ".obj, .ply, .vtp flattened) or compressed tree graph with turtle geometry "
                   "(.ctree) to write")
      ->required();
  interp->add_option("--format", interp_opts->format, "tree, treeb, nwk or mtg (default: ext)");
  interp->add_flag("--compressed", interp_opts->compressed,
                   "Derive into shared substructures and draw each once, placing its occurrences "
                   "by rigid transforms (Jaeger 3.1.2); --json adds prototypes, instances and "
                   "represented_segments");
  interp
      ->add_option("--detail", interp_opts->detail,
                   "With --compressed: draw substructures smaller than this length (model "
                   "units, box diagonal) as one internode (0: exact)")
      ->check(number_in(0.0, 1e300));
  interp->add_flag("--json", interp_opts->json, "Print a JSON summary");
  interp->callback([interp_opts] { run_reporting_command([&] { run_interpret(*interp_opts); }); });
}

}  // namespace fspm::cli
