#pragma once
// The species library of cluster texturing (Pirk sec. 3.4, Figure 3.5): branchlets derived from
// an L-system, seeded variants per species, each cut into patches. A patch is one axis of a
// branchlet with its leaves; where a lateral axis left it, the patch keeps a docking point
// (position, direction, thickness) for the patches placed after it. Axes without laterals give
// the smallest patches, which have no docking points and end the texturing. Thicknesses are base
// radii relative to the branchlet's base radius, so the patches of every branchlet compare on one
// scale and a cluster's seed point has thickness 1.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::scan_decoding {

struct DockingPoint {
  NodeId node = kNoNode;  // node of the patch the lateral axis hung from
  Eigen::Vector3d position = Eigen::Vector3d::Zero();    // in the patch frame
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit, in the patch frame
  double thickness = 0.0;  // thickn_d: radius relative to the branchlet's base radius
};

struct Patch {
  // Node 0 is the base, starting at the origin; the orientation the axis had in its branchlet is
  // kept, so `direction` is its vertical angle there.
  TreeGraph geometry;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // v_r: unit heading at the base
  double thickness = 1.0;           // thickn_r: base radius relative to the branchlet's base radius
  double length_m = 0.0;            // extent along `direction`: the largest end . direction
  double internode_length_m = 0.0;  // summed lengths of its internodes
  std::size_t leaves = 0;
  std::uint32_t branchlet = 0;
  std::vector<DockingPoint> dockings;
};

struct SpeciesLibrary {
  std::string species;
  std::vector<Patch> patches;
};

struct LibraryOptions {
  int branchlets = 8;  // seeded variants per species (Pirk uses 20-30)
  int steps = 6;       // derivation steps of each branchlet
  std::uint64_t seed = 1;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// The sizes of a species' shoots, in metres: the branchlets of the library are derived at this
// size (their first internode is the longest, the leaf blades all of one length), and texturing
// never enlarges a patch beyond it (TextureOptions::max_scale), so a decoded tree's leaves and
// patch internodes stay the species' own, whatever the size of the cluster hull.
struct SpeciesSizes {
  double leaf_length_m = 0.0;
  double internode_length_m = 0.0;
};

// Throws ValueError for an unknown species.
SpeciesSizes species_sizes(std::string_view species);

// Source of the branchlet L-system of a species of Pirk Table 3.1 ("default" too): one stochastic
// grammar whose branching angle, leaf size, droop and tropism follow the species' habit (pine:
// wide-angled needle shoots, willow: hanging shoots with narrow leaves, palm: fronds). Throws
// ValueError for an unknown species.
std::string branchlet_lsystem(std::string_view species);

// The patches of one branchlet: one per axis (a chain of internodes of one branching order), with
// its leaf children and a docking point at the base of every lateral axis. Throws ValueError when
// the branchlet has no internode at its root or its base radius is not positive.
std::vector<Patch> cut_into_patches(const TreeGraph& branchlet, std::uint32_t branchlet_index);

// Derives `options.branchlets` variants (seeds seed, seed + 1, ...) and cuts them into patches.
// Throws ValueError for an unknown species or options out of range.
SpeciesLibrary make_species_library(std::string_view species, const LibraryOptions& options = {});

}  // namespace fspm::scan_decoding
