#include "lsystem/lsystem_drawing.hpp"

#include <chrono>
#include <filesystem>

#include "fspm/atomic_file.hpp"
#include "fspm/compressed_tree_graph.hpp"
#include "fspm/count_json.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_ctree.hpp"
#include "fspm/warning.hpp"
#include "lsystem/instanced_interpretation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/substructure_derivation.hpp"

namespace fspm::lsystem {

MacroOverrides parse_defines(const std::vector<std::string>& defines) {
  MacroOverrides out;
  for (const std::string& d : defines) {
    const auto eq = d.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw ValueError("--define expects NAME=VALUE, got '" + d + "'");
    }
    out[d.substr(0, eq)] = d.substr(eq + 1);
  }
  return out;
}

DeriveOptions derive_options(const LsystemSource& source) {
  DeriveOptions d;
  if (source.steps >= 0) d.steps = source.steps;
  if (source.seed >= 0) d.seed = static_cast<std::uint64_t>(source.seed);
  d.module_budget = source.budget;
  return d;
}

LSystem read_lsystem(const LsystemSource& source) {
  return parse_lsystem_file(source.file, parse_defines(source.defines));
}

TurtleSettings view_settings(const LsystemSource& source) {
  return source.view.empty() ? view_for_lsystem(source.file) : read_view_file(source.view);
}

namespace {

LsystemDrawing draw_explicitly(const LsystemSource& source, const LSystem& sys,
                               const TurtleSettings& view) {
  DeriveOptions options = derive_options(source);
  options.turtle = &view;
  Derivation d(sys, options);
  d.run();
  Interpretation drawn = interpret(d.interpretation_string(), sys.symbols, view);
  LsystemDrawing out;
  out.summary = {{"steps", d.steps_done()},
                 {"modules", d.string().size()},
                 {"compressed", false},
                 {"nodes", drawn.tree.size()},
                 {"prototypes", 1}};
  out.tree.prototypes.push_back({std::move(drawn.tree), {}});
  out.occurrences = 1;
  return out;
}

LsystemDrawing draw_compressed(const LsystemSource& source, const LSystem& sys,
                               const TurtleSettings& view, double min_detail, int pixels) {
  const auto t0 = std::chrono::steady_clock::now();
  const SubstructureGraph graph =
      derive_substructures(sys, derive_options(source), source.variants);
  const double derive_seconds = seconds_since(t0);
  InstancedInterpretationOptions options;
  options.module_budget = source.budget;
  // Exact first: the counts of the whole plant, and its size for the level of detail.
  InstancedInterpretation exact = interpret_instanced(graph, sys, view, options);
  options.min_detail = min_detail;
  if (min_detail < 0.0) {
    const bool sized = pixels > 0 && !exact.bounds.isEmpty();
    options.min_detail = sized ? exact.bounds.sizes().maxCoeff() / pixels : 0.0;
  }
  const bool detailed = options.min_detail > 0.0 && exact.explicit_reason.empty();
  InstancedInterpretation drawn =
      detailed ? interpret_instanced(graph, sys, view, options) : std::move(exact);
  const InstancedInterpretation& whole = detailed ? exact : drawn;
  if (!drawn.explicit_reason.empty()) {
    warn(source.file + ": interpreted explicitly, not by instancing, because of " +
         drawn.explicit_reason);
  }
  std::size_t references = 0;
  for (const auto& p : drawn.tree.prototypes) references += p.children.size();
  LsystemDrawing out;
  out.summary = {{"steps", graph.steps},
                 {"compressed", true},
                 {"graph_nodes", graph.nodes.size()},
                 {"graph_bytes", graph.memory_bytes()},
                 {"derive_seconds", derive_seconds},
                 {"prototypes", drawn.tree.prototypes.size()},
                 {"child_references", references},
                 {"instances", count_json(drawn.instances)},
                 {"represented_segments", count_json(whole.internodes)},
                 {"represented_leaves", count_json(whole.leaves)},
                 {"drawn_segments", count_json(drawn.internodes)},
                 {"min_detail", options.min_detail}};
  if (source.variants > 0) out.summary["variants"] = source.variants;
  if (!drawn.explicit_reason.empty()) out.summary["explicit_reason"] = drawn.explicit_reason;
  out.tree = std::move(drawn.tree);
  out.occurrences = drawn.occurrences;
  return out;
}

}  // namespace

LsystemDrawing draw_lsystem(const LsystemSource& source, bool compressed, double min_detail,
                            int pixels) {
  const auto t0 = std::chrono::steady_clock::now();
  const LSystem sys = read_lsystem(source);
  const TurtleSettings view = view_settings(source);
  LsystemDrawing out;
  const auto obstacle =
      compressed ? factorization_obstacle(sys, source.variants > 0) : std::nullopt;
  if (obstacle) {
    const bool variants_would_do = source.variants == 0 && !factorization_obstacle(sys, true);
    warn(source.file + ": derived explicitly, not into substructures: it has " + *obstacle +
         (variants_would_do ? " (--variants K derives it with K variants per substructure)" : ""));
  }
  if (compressed && !obstacle) {
    out = draw_compressed(source, sys, view, min_detail, pixels);
  } else {
    out = draw_explicitly(source, sys, view);
    if (obstacle) out.summary["why_not_compressed"] = "it has " + *obstacle;
  }
  out.summary["seconds"] = seconds_since(t0);
  return out;
}

void write_lsystem_ctree(const LsystemDrawing& drawing, const std::string& path,
                         nlohmann::json& summary) {
  const CompressedTreeGraph graph = compress_instanced_tree(drawing.tree);
  write_ctree_file(graph, path);
  summary["ctree_records"] = graph.size();
  summary["ctree_organs"] = count_json(geometry_organ_count(graph));
  summary["ctree_bytes"] = std::filesystem::file_size(written_file(path));
}

}  // namespace fspm::lsystem
