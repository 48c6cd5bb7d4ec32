#include "scans/species.hpp"

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"

namespace fspm::scans {

const std::vector<SpeciesParameters>& species_presets() {
  // Pirk Table 3.1, "Typical parameter values of beta, gamma, and f_s".
  static const std::vector<SpeciesParameters> kPresets = {{"mahogany", 1.7, 1.3, 0.975},
                                                          {"bischofia-polycarpa", 1.8, 1.5, 0.986},
                                                          {"delonix", 1.7, 1.5, 0.982},
                                                          {"lagerstroemia", 1.6, 1.5, 0.976},
                                                          {"ailanthus-altissima", 1.5, 1.9, 0.980},
                                                          {"palm", 1.8, 1.3, 0.800},
                                                          {"terminalia", 1.5, 1.5, 0.970},
                                                          {"pine", 1.3, 1.2, 0.980},
                                                          {"willow", 1.5, 1.9, 0.980},
                                                          {"ficus-virens", 2.0, 1.6, 0.975}};
  return kPresets;
}

SpeciesParameters default_species() { return {"default", 1.6, 1.5, 0.98}; }

SpeciesParameters species_by_name(std::string_view name) {
  if (name == "default") return default_species();
  std::vector<std::string> names{"default"};
  for (const SpeciesParameters& s : species_presets()) {
    if (s.name == name) return s;
    names.push_back(s.name);
  }
  throw ValueError("unknown species '" + std::string(name) + "'" + closest_name_hint(name, names));
}

}  // namespace fspm::scans
