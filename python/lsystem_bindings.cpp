// Python bindings: deriving and interpreting L-system files.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/instanced_ctree.hpp"
#include "fspm/saturating.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/instanced_interpretation.hpp"
#include "lsystem/lsystem.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/substructure_derivation.hpp"
#include "lsystem/turtle.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

fspm::lsystem::LSystem load_lsystem(const std::string& path,
                                    const std::map<std::string, std::string>& defines) {
  return fspm::lsystem::parse_lsystem_file(path, defines);
}

// A count as Python gives it: an int, or None where it saturated at 2^64 - 1 (more than 10^19;
// fspm/saturating.hpp), so no caller computes with 18446744073709551615 as if it were the count.
py::object count_object(std::uint64_t count) {
  if (count == kSaturated) return py::none();
  return py::int_(count);
}

fspm::lsystem::DeriveOptions derive_options(std::optional<int> steps,
                                            std::optional<std::uint64_t> seed) {
  fspm::lsystem::DeriveOptions o;
  o.steps = steps;
  o.seed = seed;
  return o;
}

void bind_lsystem_derivation(py::module_& m) {
  m.def(
      "lsystem_derive",
      [](const std::string& path, std::optional<int> steps, std::optional<std::uint64_t> seed,
         const std::map<std::string, std::string>& defines, bool compressed) {
        py::dict d;
        std::vector<std::uint64_t> per_symbol;
        int done = 0;
        std::uint64_t modules = 0;
        std::size_t graph_nodes = 0, graph_bytes = 0;
        std::uint64_t explicit_bytes = 0;
        fspm::lsystem::LSystem sys;
        {
          py::gil_scoped_release release;
          sys = load_lsystem(path, defines);
          if (compressed) {
            // Shared substructures (lsystem/substructure_derivation.hpp): counts of strings too
            // large to hold; ValueError when the L-system cannot be factorized.
            const auto g = fspm::lsystem::derive_substructures(sys, derive_options(steps, seed));
            const auto c = fspm::lsystem::count_modules(g, sys.symbols.size());
            done = g.steps;
            modules = c.modules;
            per_symbol = c.per_symbol;
            graph_nodes = g.nodes.size();
            graph_bytes = g.memory_bytes();
            explicit_bytes = c.explicit_bytes;
          } else {
            fspm::lsystem::Derivation der(sys, derive_options(steps, seed));
            der.run();
            done = der.steps_done();
            modules = der.string().size();
            per_symbol.assign(sys.symbols.size(), 0);
            for (auto id : der.string().symbols()) ++per_symbol[id];
          }
        }
        py::dict symbols;
        bool saturated = modules == kSaturated || explicit_bytes == kSaturated;
        for (std::size_t i = 0; i < per_symbol.size(); ++i) {
          if (per_symbol[i] != 0) {
            symbols[py::str(sys.symbols.name(static_cast<fspm::lsystem::SymbolId>(i)))] =
                count_object(per_symbol[i]);
            saturated = saturated || per_symbol[i] == kSaturated;
          }
        }
        d["steps"] = done;
        d["modules"] = count_object(modules);
        d["symbols"] = symbols;
        d["saturated"] = saturated;
        if (compressed) {
          d["graph_nodes"] = graph_nodes;
          d["graph_bytes"] = graph_bytes;
          d["explicit_bytes"] = count_object(explicit_bytes);
          d["compression"] = static_cast<double>(explicit_bytes) /
                             static_cast<double>(std::max<std::size_t>(graph_bytes, 1));
        }
        return d;
      },
      py::arg("path"), py::arg("steps") = py::none(), py::arg("seed") = py::none(),
      py::arg("defines") = std::map<std::string, std::string>{}, py::arg("compressed") = false,
      "Derive an L-system file: steps, modules and the count of each module name; "
      "compressed=True derives into shared substructures (context-free L-systems only, "
      "docs/lsystem-language.md) and adds graph_nodes, graph_bytes, explicit_bytes and "
      "compression (explicit_bytes / graph_bytes); lsystem_plant gives the drawn plant.\n\n"
      "A count of the compressed derivation can pass 2^64 - 1 (more than 10^19 modules; ABOP "
      "Fig. 1.24a at 28 steps): such a count (modules, a value of symbols, explicit_bytes) is "
      "None and saturated is True, so no arithmetic goes on with a wrong number; compression "
      "is then a lower bound. saturated is False when every count is exact.");
}

void bind_lsystem_drawing(py::module_& m) {
  m.def(
      "lsystem_plant",
      [](const std::string& path, std::optional<int> steps, std::optional<std::uint64_t> seed,
         const std::map<std::string, std::string>& defines, bool compressed, int variants) {
        py::gil_scoped_release release;
        const fspm::lsystem::LSystem sys = load_lsystem(path, defines);
        const fspm::lsystem::TurtleSettings view = fspm::lsystem::view_for_lsystem(path);
        auto options = derive_options(steps, seed);
        fspm::InstancedTree tree;
        if (compressed) {
          // Derived into substructures and drawn by instancing (Jaeger 2.1.3, 3.1.2);
          // ValueError when the L-system cannot be factorized.
          const auto g = fspm::lsystem::derive_substructures(sys, options, variants);
          tree = fspm::lsystem::interpret_instanced(g, sys, view).tree;
        } else {
          options.turtle = &view;
          fspm::lsystem::Derivation der(sys, options);
          der.run();
          tree.prototypes.push_back(
              {fspm::lsystem::interpret(der.interpretation_string(), sys.symbols, view).tree, {}});
        }
        return fspm::compress_instanced_tree(tree);
      },
      py::arg("path"), py::arg("steps") = py::none(), py::arg("seed") = py::none(),
      py::arg("defines") = std::map<std::string, std::string>{}, py::arg("compressed") = true,
      py::arg("variants") = 0,
      "Derive and draw an L-system file into a CompressedPlant with turtle geometry (.ctree "
      "version 2): compressed=True (the default) by shared substructures drawn once each, "
      "variants=K for stochastic L-systems; greenlab_reconstruct(plant) gives the Tree and "
      "plant.save(path) the .ctree file");

  m.def(
      "lsystem_interpret",
      [](const std::string& path, std::optional<int> steps, std::optional<std::uint64_t> seed,
         const std::map<std::string, std::string>& defines) {
        py::gil_scoped_release release;
        const fspm::lsystem::LSystem sys = load_lsystem(path, defines);
        const fspm::lsystem::TurtleSettings view = fspm::lsystem::view_for_lsystem(path);
        auto options = derive_options(steps, seed);
        options.turtle = &view;
        fspm::lsystem::Derivation der(sys, options);
        der.run();
        return fspm::lsystem::interpret(der.interpretation_string(), sys.symbols, view).tree;
      },
      py::arg("path"), py::arg("steps") = py::none(), py::arg("seed") = py::none(),
      py::arg("defines") = std::map<std::string, std::string>{},
      "Derive an L-system file and draw it into a Tree");
}

}  // namespace

void bind_lsystem(py::module_& m) {
  bind_lsystem_derivation(m);
  bind_lsystem_drawing(m);
}

}  // namespace fspm::python
