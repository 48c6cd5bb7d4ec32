#pragma once
// Meshing a TreeGraph: every chain of internodes becomes one generalized cylinder (a tube of
// rings swept along the chain with parallel transport frames, Pirk 6.1.2), closed by a cap at
// each end. A chain is a maximal run of internodes without a fork (fspm::chains): it stops at
// every internode with two or more internode children, and each child, the axis's continuation
// as well as the lateral, starts a tube of its own (Pirk 6.1.3 instead continues a chain through
// the thickest child; that is not done here); leaf nodes become quads (optionally bent) placed on
// their metamer, and leaf clusters (leaf nodes of length 0 and radius > 0, as grown and adapted
// trees keep them) a cloud of leaves or a crown volume (graphics/foliage.hpp). Node columns and
// user attributes are carried to the vertices as named float attributes.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

#include "fspm/name_table.hpp"
#include "fspm/tree_graph.hpp"
#include "graphics/foliage.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

// How tubes meet at branch points.
//   kSeparate: one closed tube per chain, ending at the fork; every child starts with its own
//     cap, from the frame at its parent chain's tip.
//   kContinuous: after Reynolds 3.2, one tube per axis running through its branch points; where a
//     lateral axis starts, a knuckle ring is added on the parent at the lateral's width and the
//     lateral grows out of the quad it leaves open, sharing its four vertices, so the bark is one
//     closed surface. Vertices carry Reynolds' bone weights (graphics/bone_weights.hpp: up to
//     four bones as node ids and their weights, attributes bone0..bone3 and weight0..weight3;
//     the vertices a lateral shares with its parent weigh both). Laterals whose quad is taken, that
//     leave at a shallow angle or that hang from an axis tip fall back to separate tubes.
enum class JunctionMode { kSeparate, kContinuous };

inline constexpr NameTable<JunctionMode, 2> kJunctionModeNames{
    "junction mode",
    {{JunctionMode::kSeparate, "separate", "one tube per chain, capped at forks"},
     {JunctionMode::kContinuous, "continuous", "one closed skin through the branch points"}}};

// "separate" or "continuous", as the command line's --junctions and Python's MeshOptions name them.
std::string_view junction_mode_name(JunctionMode mode);
// Inverse of junction_mode_name; throws ValueError naming both.
JunctionMode junction_mode_from_name(std::string_view name);

// The most rings per internode MeshOptions::axis_subdivisions may ask for.
inline constexpr int kMaxAxisSubdivisions = 16;

struct MeshOptions {
  JunctionMode junctions = JunctionMode::kSeparate;
  // Radius along each axis from Reynolds' expression 1, (1 / (3 t + 1) - 0.25) / 0.75 times the
  // axis' root radius, t the fraction of the axis length, instead of the node radii
  // (continuous mode only).
  bool reynolds_width = false;
  // Ring resolution from radius: sides = ceil(2 pi r / edge_length_m), clamped to
  // [min_sides, max_sides]. One resolution per chain, taken from its base radius.
  double edge_length_m = 0.01;
  int min_sides = 3;
  int max_sides = 16;
  // Radii below this are raised to it so twigs never give degenerate triangles.
  double min_radius_m = 1e-4;
  // Level of detail from a camera: beyond lod_distance_m the target edge length grows in
  // proportion to the distance from the camera to the chain base.
  std::optional<Eigen::Vector3d> camera_m;
  double lod_distance_m = 5.0;
  // Close every tube with a cap at its base and its tip.
  bool caps = true;
  // Rings per internode along each chain's axis, refined by uniform cubic B-splines (Pirk
  // 6.1.4, eq. 6.6-6.7; bspline_refinement.hpp): 1 keeps one ring at every joint (straight
  // internodes); s > 1 rounds the axis through s rings per internode, the chain's ends kept in
  // place. Separate junctions only.
  int axis_subdivisions = 1;

  bool bark = true;  // internode tubes (false: leaves only)
  bool leaves = false;
  double leaf_width_ratio = 0.5;  // leaf blade width / leaf length
  // Droop of the blade tip as a fraction of its length (0 = flat quad).
  double leaf_bend = 0.0;
  int leaf_bend_segments = 4;
  // Leaf clusters (with leaves on): how they are drawn, and the seed of the generator placing
  // their leaves (same seed, same mesh).
  FoliageOptions foliage;
  std::uint64_t foliage_seed = 1;

  // Growth sequences: nodes born after this time (and their subtrees) are left out, and the
  // "age" attribute is measured from it. Infinity = keep all, age measured from the latest birth.
  double max_birth_time = std::numeric_limits<double>::infinity();

  // Leaves and leaf clusters carry the bone they move with (attributes bone0 = the nearest
  // internode at or above them, weight0 = 1), as the bark of continuous meshes does; set by the
  // continuous mesher so skins move the foliage with its branch.
  bool leaf_bones = false;

  // Throws ValueError naming the first field out of range (the foliage's too, with leaves on).
  void validate() const;
};

// Per-vertex attributes every mesh carries, followed by the tree's user attributes.
inline constexpr const char* kAttributeAge = "age";
inline constexpr const char* kAttributeBirthTime = "birth_time";
inline constexpr const char* kAttributeOrder = "order";
inline constexpr const char* kAttributePhysiologicalAge = "physiological_age";

struct MeshCounts {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t tubes = 0;
  std::size_t leaves = 0;    // leaf nodes drawn as quads
  std::size_t clusters = 0;  // leaf clusters drawn as foliage
};

// Ring resolution for a radius at a distance from the camera (0 without a camera).
int sides_for_radius(double radius_m, const MeshOptions& options, double distance_m = 0.0);

// What mesh_tree will produce, without building it. Throws ValueError for bad options.
MeshCounts count_mesh(const TreeGraph& tree, const MeshOptions& options = {});

// Throws ValueError for bad options or more than 2^32 vertices.
TriangleMesh mesh_tree_continuous(const TreeGraph& tree, const MeshOptions& options);

// Throws ValueError for bad options or more than 2^32 vertices.
TriangleMesh mesh_tree(const TreeGraph& tree, const MeshOptions& options = {});

}  // namespace fspm::graphics
