#pragma once
// An L-system file as the commands name it: file, steps, seed, #define overrides, module budget
// and view file; shared by `fspm lsystem` and the graphics commands that draw L-systems.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lsystem/lsystem_drawing.hpp"

namespace CLI {
class App;
}

namespace fspm::cli {

// The drawing itself is the L-system library's (lsystem/lsystem_drawing.hpp).
using lsystem::derive_options;
using lsystem::draw_lsystem;
using lsystem::LsystemDrawing;
using lsystem::LsystemSource;
using lsystem::parse_defines;
using lsystem::read_lsystem;
using lsystem::view_settings;
using lsystem::write_lsystem_ctree;

// Writes a drawing as a mesh: .glb keeps the instances, .obj, .ply and .vtp get the flattened
// mesh (refused above the memory limit); adds vertices and triangles to `summary`. Defined in
// fspm-full (cli/lsystem_mesh.cpp); fspm hands command lines with a mesh output over to it.
void write_lsystem_mesh(const LsystemDrawing& drawing, const std::string& path,
                        nlohmann::json& summary);

// A mesh format fspm writes other than the .pvd sequence: .obj, .ply, .vtp or .glb (any case;
// fspm/file_kind.hpp).
bool is_mesh_path(const std::string& path);
// .ctree (any case).
bool is_ctree_path(const std::string& path);

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
