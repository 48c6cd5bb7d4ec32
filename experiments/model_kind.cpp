#include "experiments/model_kind.hpp"

namespace fspm::experiments {

std::string_view model_kind_name(ModelKind kind) {
  switch (kind) {
    case ModelKind::kLSystem:
      return "lsystem";
    case ModelKind::kGreenLab:
      return "greenlab";
    case ModelKind::kGrow:
      return "grow";
    case ModelKind::kAdapt:
      return "adapt";
    case ModelKind::kStages:
      return "stages";
    case ModelKind::kSynthetic:
      return "synthetic";
  }
  return "synthetic";
}

std::optional<ModelKind> find_model_kind(std::string_view name) {
  for (ModelKind kind : kModelKinds) {
    if (model_kind_name(kind) == name) return kind;
  }
  return std::nullopt;
}

std::string model_kind_names() {
  std::string out;
  for (std::size_t i = 0; i < kModelKinds.size(); ++i) {
    if (i > 0) out += i + 1 == kModelKinds.size() ? " or " : ", ";
    out += model_kind_name(kModelKinds[i]);
  }
  return out;
}

}  // namespace fspm::experiments
