#include "experiments/greenlab_model.hpp"

#include <cmath>
#include <random>

#include "experiments/metrics.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/functional.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/simulation.hpp"

namespace fspm::experiments {
namespace {

class GreenLabModel final : public Model {
 public:
  explicit GreenLabModel(const std::string& file) : base_(greenlab::read_plant_params(file)) {}

  void check_parameter(const std::string& name, const ParameterValue& value) const override {
    if (name == "cycles") {
      const std::int64_t c = parameter_integer(value, name);
      if (c < 1 || c > greenlab::kMaxCycles) {
        throw ValueError("cycles must lie in 1.." + std::to_string(greenlab::kMaxCycles));
      }
      return;
    }
    greenlab::PlantParams p = base_;
    greenlab::set_parameter(p, name, parameter_number(value, name));
  }

  void check_setup(const ParameterSet& parameters) const override {
    params_for(parameters).validate();
  }

  // The plant's organ count, and with it the reconstruction, grows with the cycles.
  double cost_estimate(const ParameterSet& parameters) const override {
    try {
      return static_cast<double>(params_for(parameters).cycles);
    } catch (const std::exception&) {
      return 1.0;
    }
  }

  RunResult run(const ParameterSet& parameters, std::uint64_t seed,
                const RunContext& context) const override {
    const greenlab::PlantParams p = params_for(parameters);
    p.validate();
    std::mt19937_64 rng(seed);
    CompressedTreeGraph graph = greenlab::simulate_compressed(p, rng, p.cycles);
    context.check();
    RunResult result;
    double biomass = std::nan("");
    if (p.functional.enabled) {
      const greenlab::Gl1Result gl1 = greenlab::apply_functional(p, graph);
      biomass = 0.0;
      for (double q : gl1.production) biomass += q;
      context.check();
    }
    TreeGraph tree = greenlab::reconstruct(graph, greenlab::ReconstructionOptions{});
    result.metrics = tree_metrics(tree);
    result.metrics["biomass"] = biomass;
    result.tree = std::move(tree);
    return result;
  }

 private:
  greenlab::PlantParams params_for(const ParameterSet& parameters) const {
    greenlab::PlantParams p = base_;
    for (const auto& [name, value] : parameters) {
      if (name == "cycles") {
        p.cycles = static_cast<int>(parameter_integer(value, name));
      } else {
        greenlab::set_parameter(p, name, parameter_number(value, name));
      }
    }
    return p;
  }

  greenlab::PlantParams base_;
};

}  // namespace

std::unique_ptr<Model> make_greenlab_model(const std::string& plant_file) {
  return std::make_unique<GreenLabModel>(plant_file);
}

}  // namespace fspm::experiments
