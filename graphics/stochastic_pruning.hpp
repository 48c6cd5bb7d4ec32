#pragma once
// Stochastic pruning of leaves (Cook et al. 2007; Pirk 2013, section 3.5.2): the leaves are
// stored once in random order and only a prefix of that buffer is drawn, its leaves enlarged by
// sqrt(N / n) about their centroids so the drawn leaf area stays that of all N leaves. The order
// comes from a seeded generator: the same seed prunes the same leaves, and a longer prefix
// always contains a shorter one (no popping between levels).
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

struct LeafBuffer {
  TriangleMesh bark;                  // every triangle that is not a leaf, kept at every level
  TriangleMesh leaves;                // leaf triangles, leaf by leaf in random order
  std::vector<std::size_t> leaf_end;  // leaf k's triangles end at leaf_end[k]

  std::size_t leaf_count() const { return leaf_end.size(); }
};

// Leaves are the connected groups of leaf-material triangles (sharing vertex indices); their
// order is shuffled with `rng`.
LeafBuffer make_leaf_buffer(const TriangleMesh& mesh, std::mt19937_64& rng);

// Leaves drawn for a share `fraction` of the leaf count: ceil(fraction N), at least 1 when there
// are leaves and fraction > 0. Throws ValueError for a fraction outside [0, 1].
std::size_t pruned_leaf_count(std::size_t leaves, double fraction);

// Cook et al.: the share of elements drawn follows the tree's projected area, which falls with
// the square of the distance: (reference_distance / distance)^2, at most 1.
double pruning_fraction(double distance_m, double reference_distance_m);

// The bark and the first `count` leaves, each enlarged by sqrt(N / count) about its centroid.
TriangleMesh pruned_mesh(const LeafBuffer& buffer, std::size_t count);

}  // namespace fspm::graphics
