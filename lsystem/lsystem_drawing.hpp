#pragma once
// An L-system file drawn by the turtle, as the commands and Python open it: the file with its
// steps, seed, #define overrides, module budget and view file, derived explicitly or into shared
// substructures (Jaeger 3.1.2) and drawn as prototypes and placements.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "fspm/instanced_tree.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/lsystem.hpp"
#include "lsystem/preprocessor.hpp"
#include "lsystem/turtle.hpp"

namespace fspm::lsystem {

struct LsystemSource {
  std::string file;
  int steps = -1;                    // < 0: the file's derivation length
  std::int64_t seed = -1;            // < 0: the file's seed
  std::vector<std::string> defines;  // NAME=VALUE
  std::size_t budget = kDefaultModuleBudget;
  std::string view;  // empty: the .v beside the file
  // > 0: stochastic L-systems derived into substructures with this many variants each
  // (derive_substructures).
  int variants = 0;
};

// NAME=VALUE pairs; throws ValueError for anything else.
MacroOverrides parse_defines(const std::vector<std::string>& defines);
DeriveOptions derive_options(const LsystemSource& source);
LSystem read_lsystem(const LsystemSource& source);
TurtleSettings view_settings(const LsystemSource& source);

// An L-system drawn by the turtle, as prototypes and placements, with a summary for --json.
struct LsystemDrawing {
  InstancedTree tree;
  std::uint64_t occurrences = 0;  // of all prototypes
  nlohmann::json summary;
};

// Derives and draws `source`. `compressed`: into substructures, drawn by instancing (Jaeger
// 3.1.2) when the L-system allows it, with a warning (fspm::warn) naming the reason when it does
// not (then explicitly, as one prototype). `min_detail` (compressed only): substructures smaller
// than this drawn as one internode (InstancedInterpretationOptions); < 0: the plant's largest
// extent divided by `pixels`, about one pixel of a picture showing the whole plant.
LsystemDrawing draw_lsystem(const LsystemSource& source, bool compressed, double min_detail,
                            int pixels);

// Writes a drawing as a compressed tree graph with turtle geometry (.ctree version 2,
// fspm/instanced_ctree.hpp) that fspm greenlab reconstruct, mesh, render and view read; adds
// ctree_records, ctree_organs (internodes, leaves and flowers it stands for) and ctree_bytes to
// `summary`.
void write_lsystem_ctree(const LsystemDrawing& drawing, const std::string& path,
                         nlohmann::json& summary);

}  // namespace fspm::lsystem
