#pragma once
// Trees in the wind on the command line: `fspm mesh TREE --skin [--animate SECONDS]` writes a
// skinned glTF with a wind animation, `fspm render TREE --wind-time T` draws the same tree posed
// at time T of that animation (frames for a movie).
#include <CLI/CLI.hpp>
#include <Eigen/Geometry>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"
#include "graphics/wind_animation.hpp"

namespace fspm::cli {

struct WindArguments {
  // --wind-frequency, --fps and --wind-period bound straight into the wind model's options, whose
  // defaults are theirs.
  graphics::WindOptions options;
  // The sway in degrees on the command line; its default is the model's.
  double amplitude_deg = options.amplitude_rad * 180.0 / std::numbers::pi;
  std::vector<double> direction;  // X, Y; empty: the model's (+x)
};

// --wind-amplitude, --wind-frequency, --wind-direction (and --fps when `frames`).
void add_wind_options(CLI::App* command, WindArguments& wind, bool frames);

// The wind model's options for a clip `duration_s` long; the seed draws the phases.
graphics::WindOptions wind_options(const WindArguments& wind, double duration_s,
                                   std::uint64_t seed);

// The tree meshed with continuous (Reynolds) junctions, which carry the bone weights a skin
// needs; leaves and leaf clusters follow the internode they grow on.
graphics::TriangleMesh skinnable_mesh(const TreeGraph& tree, graphics::MeshOptions options);

struct SkinnedOutput {
  std::size_t joints = 0, vertices = 0, triangles = 0, keyframes = 0;
};

// `fspm mesh --skin`: the skinned .glb with the wind animation when duration_s > 0.
SkinnedOutput write_wind_glb(const TreeGraph& tree, const graphics::MeshOptions& options,
                             const WindArguments& wind, double duration_s, std::uint64_t seed,
                             const std::string& path);

struct WindFrame {
  graphics::TriangleMesh mesh;  // posed
  // The camera's box, the same at every time: the tree at rest grown by a tenth of its height
  // sideways and upwards (not below the ground), so the frames of a movie line up.
  Eigen::AlignedBox3f frame;
};

// The mesh posed at time t of the wind animation (`fspm render --wind-time`).
WindFrame posed_in_wind(const TreeGraph& tree, const graphics::MeshOptions& options,
                        const WindArguments& wind, double t_s, std::uint64_t seed);

}  // namespace fspm::cli
