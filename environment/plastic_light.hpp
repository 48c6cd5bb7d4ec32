#pragma once
// The light of leaf clusters in the analysis and plastic adaptation of a grown tree (Pirk
// 4.3-4.4), one implementation per light model (`canopy_plastic_light.cpp`,
// `sky_plastic_light.cpp`, `shadow_grid_plastic_light.cpp`), created through the registry of
// light models (light_model_registry.hpp) from AnalysisParams::light_model. The analysis asks it
// for the light of one tree's clusters in the open; the adaptation asks it once at the start and
// after every step, and the model decides what to light again: everything that changed
// (the whole crown) or only the clusters the moves and pruning can have reached.
#include <memory>
#include <string_view>

#include "environment/adaptation_state.hpp"
#include "environment/cluster_light.hpp"
#include "environment/light_model_registry.hpp"
#include "environment/scene.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

class PlasticLight {
 public:
  virtual ~PlasticLight() = default;

  // The light of the analysed tree's clusters alone in the open scene `open` (its sky only):
  // a.cluster_light, a.cluster_direction and a.cluster_neighbors (the neighbour lists the
  // adaptation may start from; empty lists for a model without them), one per cluster. `field`
  // is the analysis' light field (its sky directions, nothing set).
  virtual void analyse(const TreeGraph& tree, const Scene& open, ClusterLightField& field,
                       TreeAnalysis& a) = 0;

  // The adaptation starts: every alive cluster of s.field gets its light in s.scene (the
  // analysis' when nothing differs from the open scene).
  virtual void start(AdaptationState& s) = 0;
  // After a step's moves (s.moved) or prunings (s.vanished): the light of the clusters that may
  // have changed, counting an epoch when it set any.
  virtual void update(AdaptationState& s) = 0;
  // True when the model lights the whole crown again after any move (the engine then counts a
  // move as a change, so that update() sees it in s.epoch).
  virtual bool relights_crown() const { return false; }
};

// The model `params.light_model` names; ValueError (after `context`) when it has no cluster light.
std::unique_ptr<PlasticLight> make_plastic_light(const AnalysisParams& params,
                                                 std::string_view context = {});

}  // namespace fspm::environment
