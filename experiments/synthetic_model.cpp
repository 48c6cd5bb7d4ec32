#include "experiments/synthetic_model.hpp"

#include <thread>

#include "experiments/metrics.hpp"

namespace fspm::experiments {
namespace {

double number_or(const ParameterSet& p, const std::string& name, double fallback) {
  const auto it = p.find(name);
  if (it == p.end()) return fallback;
  try {
    return parameter_number(it->second, name);
  } catch (const std::exception&) {
    return fallback;
  }
}

class SyntheticModel final : public Model {
 public:
  void check_parameter(const std::string& name, const ParameterValue& value) const override {
    if (name == "nodes" || name == "fail") {
      if (parameter_integer(value, name) < 0) throw ValueError(name + " must not be negative");
    } else if (name == "length" || name == "sleep_ms") {
      if (parameter_number(value, name) < 0.0) throw ValueError(name + " must not be negative");
    } else if (!name.starts_with("x.")) {
      throw ValueError("unknown parameter '" + name +
                       "' for model kind synthetic (expected nodes, length, sleep_ms, fail or "
                       "x.NAME)");
    }
  }

  // Its sleep, plus about 0.1 microsecond per node built.
  double cost_estimate(const ParameterSet& p) const override {
    return number_or(p, "sleep_ms", 0.0) + 1e-4 * number_or(p, "nodes", 10.0);
  }

  RunResult run(const ParameterSet& p, std::uint64_t /*seed*/,
                const RunContext& context) const override {
    auto get = [&](const std::string& name, double fallback) {
      const auto it = p.find(name);
      return it == p.end() ? fallback : parameter_number(it->second, name);
    };
    if (get("fail", 0.0) != 0.0) throw ValueError("synthetic failure");
    const double sleep_ms = get("sleep_ms", 0.0);
    if (sleep_ms > 0.0) {
      const auto until =
          RunContext::Clock::now() + std::chrono::duration_cast<RunContext::Clock::duration>(
                                         std::chrono::duration<double, std::milli>(sleep_ms));
      while (RunContext::Clock::now() < until) {
        context.check();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    }
    const auto nodes = static_cast<std::size_t>(get("nodes", 10.0));
    const double length = get("length", 1.0);
    RunResult result;
    TreeGraph tree;
    tree.reserve(nodes);
    NodeId parent = kNoNode;
    for (std::size_t i = 0; i < nodes; ++i) {
      NodeData d;
      d.start = Eigen::Vector3d(0.0, 0.0, static_cast<double>(i) * length);
      d.end = Eigen::Vector3d(0.0, 0.0, static_cast<double>(i + 1) * length);
      parent = tree.add_node(parent, d);
    }
    result.metrics = tree_metrics(tree);
    result.tree = std::move(tree);
    return result;
  }
};

}  // namespace

std::unique_ptr<Model> make_synthetic_model() { return std::make_unique<SyntheticModel>(); }

}  // namespace fspm::experiments
