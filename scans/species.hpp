#pragma once
// Species parameters of the cluster-based representation (Pirk Table 3.1): beta, the exponent
// of the edge weight |u - v|^beta of the neighbour graph (sec. 3.3.1); gamma, the allometric
// exponent of eq. 3.1; f_s, the diameter factor of eq. 3.2 that decides the clusters.
#include <string>
#include <string_view>
#include <vector>

namespace fspm::scans {

struct SpeciesParameters {
  std::string name;
  double beta = 1.6;
  double gamma = 1.5;
  double f_s = 0.98;
};

// The ten presets of Table 3.1, in its order, with lower-case names ("mahogany",
// "bischofia-polycarpa", "delonix", "lagerstroemia", "ailanthus-altissima", "palm",
// "terminalia", "pine", "willow", "ficus-virens").
const std::vector<SpeciesParameters>& species_presets();
// The values used when no species is given (named "default"): beta 1.6, gamma 1.5, f_s 0.98,
// near the middle of Table 3.1.
SpeciesParameters default_species();
// The preset named `name` ("default" too); throws ValueError listing the names (and the closest).
SpeciesParameters species_by_name(std::string_view name);

}  // namespace fspm::scans
