#pragma once
// The profile diagram of the pipe model theory (Shinozaki et al. 1964, Chiba 1990; Pirk 5.3.4): per
// horizontal layer of the tree, the leaves Γ(z) and the non-photosynthetic tissue C(z), and their
// sums from the top down, F(z) and T(z). Two ways of gathering them (Pirk 5.3.4):
//   - stratified clipping (STC): what lies in the layer [z, z + Δz];
//   - main-axis cutting (MAC): what emerges from the main-axis segment [z, z + Δz], a branch
//     wholly at the height where it leaves the main axis.
// Pirk finds the overlap regions of 5.3.5 where T(z) by STC clearly exceeds T(z) by MAC (the
// biomass there hangs from elsewhere on the axis); that filling is not built yet.
#include <cstdint>
#include <string_view>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::stages {

enum class Clipping : std::uint8_t { kStratified, kMainAxis };

// "stratified", "main_axis".
std::string_view clipping_name(Clipping clipping);

struct ProfileDiagram {
  double layer_m = 0.0;         // Δz; layer k spans [k Δz, (k + 1) Δz] above the root's base
  std::vector<double> leaves;   // Γ: leaves per layer (count)
  std::vector<double> wood_m3;  // C: internode volume π r² l per layer
  std::vector<double> leaves_above;  // F: leaves in this layer and above, share of all leaves
  // T: tissue in this layer and above, as the mean of the leaf share and the wood share (the tree
  // graph has no leaf masses to add leaves and wood by weight).
  std::vector<double> tissue_above;
};

// `chain` per node as DevelopmentalModel::chain() (0: the main axis). Throws ValueError for
// layer_m <= 0 or a chain vector of the wrong size. An internode's wood is split over the layers
// its segment crosses in proportion to its height in each (STC, and MAC on the main axis).
ProfileDiagram profile_diagram(const TreeGraph& tree, const std::vector<std::uint32_t>& chain,
                               double layer_m, Clipping clipping);

}  // namespace fspm::stages
