#pragma once
// One interface for the light of a crown's leaf clusters, shared by growth (the leaves' attribute
// "light", leaf_light.hpp) and the plastic adaptation (its cluster light `canopy`,
// tree_analysis.hpp). A model is one file defining its factory and one line in the table of
// leaf_light_model.cpp; growth and adaptation then take it by name.
#include <Eigen/Core>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "environment/hemisphere.hpp"
#include "environment/light_model.hpp"
#include "environment/scene.hpp"

namespace fspm::environment {

class LeafLightModel {
 public:
  virtual ~LeafLightModel() = default;
  // The mean light of each cluster's leaves relative to the open sky (the cos^2 sky of Pirk eq.
  // 4.3 over the model's sky directions) and its mean direction, with every cluster (its own
  // included) a turbid medium and the obstacles given by their transmission per direction of
  // HemisphereDirections(sky.directions): visibility[k] at cluster k (empty: open sky), or
  // visibility empty for a scene without obstacles.
  virtual void evaluate(std::span<const Sphere> clusters,
                        std::span<const std::span<const float>> visibility,
                        std::span<LightSample> out) = 0;
};

using LeafLightFactory = std::unique_ptr<LeafLightModel> (*)(const Sky& sky);

struct LeafLightModelEntry {
  const char* name;
  const char* summary;
  LeafLightFactory make;
};

// Every registered model, in the order of the table.
std::span<const LeafLightModelEntry> leaf_light_models();
// Throws ValueError naming the registered models when `name` is not one of them.
std::unique_ptr<LeafLightModel> make_leaf_light_model(const std::string& name, const Sky& sky);
// "turbid, sweep": the registered names, for messages and help texts.
std::string leaf_light_model_names();

// The growth model's leaves' light (leaf_light.hpp) and the adaptation's default `canopy` model.
inline constexpr const char* kGrowthLeafLightModel = "turbid";
inline constexpr const char* kAdaptationLeafLightModel = "sweep";

// Transmission of the scene's obstacles (not its leaf clusters: the spheres of `scene.spheres`
// count as obstacles here) along each direction of `dirs` from p, each obstacle crossed once
// multiplying by its translucency (eq. 4.3); empty when nothing is in the way.
std::vector<float> obstacle_visibility(const Scene& scene, const HemisphereDirections& dirs,
                                       const Eigen::Vector3d& p);
// The same along one unit direction d.
double obstacle_transmission(const Scene& scene, const Eigen::Vector3d& p,
                             const Eigen::Vector3d& d);

}  // namespace fspm::environment
