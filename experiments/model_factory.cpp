#include "experiments/model_factory.hpp"

#include <filesystem>

#include "experiments/adapt_model.hpp"
#include "experiments/greenlab_model.hpp"
#include "experiments/grow_model.hpp"
#include "experiments/lsystem_model.hpp"
#include "experiments/stages_model.hpp"
#include "experiments/synthetic_model.hpp"

namespace fspm::experiments {
namespace {

void require_file(const Experiment& x) {
  if (x.model_file.empty()) {
    throw ValueError("model.file: missing (model kind " +
                         std::string(model_kind_name(x.model_kind)) + " needs a file)",
                     x.path, x.model_kind_line);
  }
}

// Folder that relative scene parameters are resolved against: the experiment file's.
std::string base_dir(const Experiment& x) {
  const std::string dir = x.path == "<string>"
                              ? std::string(".")
                              : std::filesystem::path(x.path).parent_path().string();
  return dir.empty() ? "." : dir;
}

}  // namespace

std::unique_ptr<Model> make_model(const Experiment& x) {
  switch (x.model_kind) {
    case ModelKind::kLSystem: {
      require_file(x);
      bool defines = false;
      for (const auto& [name, line] : x.parameter_lines)
        defines = defines || name.starts_with("define.");
      return make_lsystem_model(x.model_file, x.model_view, defines);
    }
    case ModelKind::kGreenLab:
      require_file(x);
      return make_greenlab_model(x.model_file);
    case ModelKind::kGrow:
      return make_grow_model(x.model_file, x.model_scene, base_dir(x));
    case ModelKind::kAdapt:
      require_file(x);
      return make_adapt_model(x.model_file, x.model_scene, base_dir(x));
    case ModelKind::kStages:
      require_file(x);
      return make_stages_model(x.model_file);
    case ModelKind::kSynthetic:
      return make_synthetic_model();
  }
  throw ValueError("model.kind: unknown kind", x.path, x.model_kind_line);
}

void check_experiment(const Experiment& x, const Model& model, const RunPlan& plan) {
  auto check = [&](const std::string& name, const ParameterValue& value) {
    try {
      model.check_parameter(name, value);
    } catch (const Error& e) {
      const auto it = x.parameter_lines.find(name);
      throw ValueError(name + ": " + e.message(), x.path,
                       it == x.parameter_lines.end() ? 0 : it->second);
    }
  };
  for (const auto& [name, value] : x.fixed) check(name, value);
  for (const SweepAxis& axis : x.sweep) {
    for (const ParameterValue& v : axis.values) check(axis.name, v);
  }
  if (x.sampling) {
    for (const SampledParameter& p : x.sampling->parameters) {
      if (p.integer) {
        check(p.name, static_cast<std::int64_t>(p.low));
        check(p.name, static_cast<std::int64_t>(p.high));
      } else {
        check(p.name, p.low);
        check(p.name, p.high);
      }
    }
  }
  if (plan.size() > 0) model.check_setup(plan.run(0).parameters);
}

}  // namespace fspm::experiments
