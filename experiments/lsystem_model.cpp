#include "experiments/lsystem_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

#include "experiments/metrics.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/preprocessor.hpp"
#include "lsystem/turtle.hpp"

namespace fspm::experiments {
namespace {

constexpr std::string_view kDefine = "define.";
constexpr std::string_view kTurtle = "turtle.";

double* turtle_field(lsystem::TurtleSettings& t, std::string_view name) {
  if (name == "angle_deg") return &t.angle_deg;
  if (name == "step") return &t.step;
  if (name == "initial_line_width") return &t.initial_line_width;
  if (name == "line_width_increment") return &t.line_width_increment;
  if (name == "initial_elasticity") return &t.initial_elasticity;
  if (name == "elasticity_increment") return &t.elasticity_increment;
  return nullptr;
}

class LSystemModel final : public Model {
 public:
  LSystemModel(std::string file, const std::string& view, bool has_defines)
      : file_(std::move(file)) {
    view_ = view.empty() ? lsystem::view_for_lsystem(file_) : lsystem::read_view_file(view);
    // Without #define overrides every run derives the same grammar: parse it once.
    if (!has_defines) shared_.emplace(lsystem::parse_lsystem_file(file_));
  }

  void check_parameter(const std::string& name, const ParameterValue& value) const override {
    if (name == "steps") {
      if (parameter_integer(value, name) < 0) throw ValueError("steps must not be negative");
      return;
    }
    if (name.starts_with(kDefine)) {
      if (name.size() == kDefine.size()) throw ValueError("define. needs a macro name");
      // A macro the grammar never uses would make every run identical: the preprocessor refuses
      // it, and the caller adds the experiment file's line.
      try {
        lsystem::preprocess_file(file_, {{name.substr(kDefine.size()), "0"}});
      } catch (const ValueError& e) {
        throw ValueError(e.message());
      }
      return;
    }
    if (name.starts_with(kTurtle)) {
      lsystem::TurtleSettings t;
      if (turtle_field(t, std::string_view(name).substr(kTurtle.size())) == nullptr) {
        throw ValueError("unknown turtle setting '" + name +
                         "' (expected turtle.angle_deg, turtle.step, turtle.initial_line_width, "
                         "turtle.line_width_increment, turtle.initial_elasticity, "
                         "turtle.elasticity_increment)");
      }
      parameter_number(value, name);
      return;
    }
    throw ValueError("unknown parameter '" + name +
                     "' for model kind lsystem (expected steps, define.NAME or turtle.SETTING)");
  }

  void check_setup(const ParameterSet& parameters) const override {
    if (!shared_) lsystem::parse_lsystem_file(file_, overrides(parameters));
  }

  // Module strings of branching L-systems grow geometrically with the derivation steps; runs
  // without `steps` all derive the file's length and cost the same.
  double cost_estimate(const ParameterSet& parameters) const override {
    const auto it = parameters.find("steps");
    if (it == parameters.end()) return 1.0;
    try {
      return std::pow(2.0, static_cast<double>(std::min<std::int64_t>(
                               parameter_integer(it->second, "steps"), 1000)));
    } catch (const std::exception&) {
      return 1.0;
    }
  }

  RunResult run(const ParameterSet& parameters, std::uint64_t seed,
                const RunContext& context) const override {
    std::optional<lsystem::LSystem> own;
    const lsystem::LSystem* system = shared_ ? &*shared_ : nullptr;
    if (system == nullptr)
      system = &own.emplace(lsystem::parse_lsystem_file(file_, overrides(parameters)));
    lsystem::TurtleSettings turtle = view_;
    lsystem::DeriveOptions options;
    options.seed = seed;
    options.turtle = &turtle;
    for (const auto& [name, value] : parameters) {
      if (name == "steps") options.steps = static_cast<int>(parameter_integer(value, name));
      if (name.starts_with(kTurtle)) {
        *turtle_field(turtle, std::string_view(name).substr(kTurtle.size())) =
            parameter_number(value, name);
      }
    }
    context.check();
    lsystem::Derivation derivation(*system, options);
    // Step by step so that a run over its time limit stops between steps; run() does the last
    // step and the end: block.
    while (derivation.steps_done() + 1 < derivation.target_steps()) {
      derivation.step();
      context.check();
    }
    derivation.run();
    context.check();
    const lsystem::ModuleString drawn = derivation.interpretation_string();
    lsystem::Interpretation interpretation = lsystem::interpret(drawn, system->symbols, turtle);
    RunResult result;
    result.metrics = tree_metrics(interpretation.tree);
    result.tree = std::move(interpretation.tree);
    return result;
  }

 private:
  static lsystem::MacroOverrides overrides(const ParameterSet& parameters) {
    lsystem::MacroOverrides o;
    for (const auto& [name, value] : parameters) {
      if (name.starts_with(kDefine)) o[name.substr(kDefine.size())] = parameter_text(value);
    }
    return o;
  }

  std::string file_;
  lsystem::TurtleSettings view_;
  std::optional<lsystem::LSystem> shared_;
};

}  // namespace

std::unique_ptr<Model> make_lsystem_model(const std::string& lsystem_file,
                                          const std::string& view_file,
                                          bool has_define_parameters) {
  return std::make_unique<LSystemModel>(lsystem_file, view_file, has_define_parameters);
}

}  // namespace fspm::experiments
