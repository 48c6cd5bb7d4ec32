#pragma once
// An L-system file as the commands name it: file, steps, seed, #define overrides, module budget
// and view file; shared by `fspm lsystem` and the graphics commands that draw L-systems.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fspm/instanced_tree.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/lsystem.hpp"
#include "lsystem/preprocessor.hpp"
#include "lsystem/turtle.hpp"

namespace CLI {
class App;
}

namespace fspm::cli {

struct LsystemSource {
  std::string file;
  int steps = -1;                    // < 0: the file's derivation length
  std::int64_t seed = -1;            // < 0: the file's seed
  std::vector<std::string> defines;  // NAME=VALUE
  std::size_t budget = lsystem::kDefaultModuleBudget;
  std::string view;  // empty: the .v beside the file
  // > 0: stochastic L-systems derived into substructures with this many variants each
  // (lsystem::derive_substructures).
  int variants = 0;
};

// NAME=VALUE pairs; throws ValueError for anything else.
lsystem::MacroOverrides parse_defines(const std::vector<std::string>& defines);
lsystem::DeriveOptions derive_options(const LsystemSource& source);
lsystem::LSystem read_lsystem(const LsystemSource& source);
lsystem::TurtleSettings view_settings(const LsystemSource& source);

// An L-system drawn by the turtle, as prototypes and placements, with a summary for --json.
struct LsystemDrawing {
  InstancedTree tree;
  std::uint64_t occurrences = 0;  // of all prototypes
  nlohmann::json summary;
};

// Derives and draws `source`. `compressed`: into substructures, drawn by instancing (Jaeger
// 3.1.2) when the L-system allows it, with a warning naming the reason when it does not (then
// explicitly, as one prototype). `min_detail` (compressed only): substructures smaller than this
// drawn as one internode (lsystem::InstancedInterpretationOptions); < 0: the plant's largest
// extent divided by `pixels`, about one pixel of a picture showing the whole plant.
LsystemDrawing draw_lsystem(const LsystemSource& source, bool compressed, double min_detail,
                            int pixels);

// Writes a drawing as a mesh: .glb keeps the instances, .obj, .ply and .vtp get the flattened
// mesh (refused above the memory limit); adds vertices and triangles to `summary`. Defined in
// fspm-full (cli/lsystem_mesh.cpp); fspm hands command lines with a mesh output over to it.
void write_lsystem_mesh(const LsystemDrawing& drawing, const std::string& path,
                        nlohmann::json& summary);

// .obj, .ply, .vtp or .glb (any case).
bool is_mesh_path(const std::string& path);
// .ctree (any case).
bool is_ctree_path(const std::string& path);

// Writes a drawing as a compressed tree graph with turtle geometry (.ctree version 2,
// fspm/instanced_ctree.hpp) that fspm greenlab reconstruct, mesh, render and view read; adds
// ctree_records, ctree_organs (internodes, leaves and flowers it stands for) and ctree_bytes to
// `summary`.
void write_lsystem_ctree(const LsystemDrawing& drawing, const std::string& path,
                         nlohmann::json& summary);

// The L-system options of the commands that draw files of several kinds (render, mesh, view),
// declared once: --compressed, --variants, --steps.
struct LsystemDrawArguments {
  bool compressed = false;
  int variants = 0;
  int steps = -1;
  bool given() const { return compressed || variants > 0 || steps >= 0; }
};
void add_lsystem_draw_options(CLI::App* command, LsystemDrawArguments& arguments);
// The source of `file` drawn with `arguments`; throws ValueError when arguments were given and
// `file` is not an L-system (.l).
LsystemSource lsystem_draw_source(const std::string& file, const LsystemDrawArguments& arguments);
// Throws ValueError when arguments were given but none of `files` is an L-system.
void check_lsystem_draw_arguments(const LsystemDrawArguments& arguments,
                                  const std::vector<std::string>& files);
// .l (any case).
bool is_lsystem_path(const std::string& path);

}  // namespace fspm::cli
