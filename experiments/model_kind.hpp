#pragma once
// The model kinds an experiment file names in `[model] kind`, as an enum with one name table:
// the parser, the model factory, the report and the renders all switch on the enum.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace fspm::experiments {

enum class ModelKind : std::uint8_t { kLSystem, kGreenLab, kGrow, kAdapt, kStages, kSynthetic };

inline constexpr std::array<ModelKind, 6> kModelKinds = {
    ModelKind::kLSystem, ModelKind::kGreenLab, ModelKind::kGrow,
    ModelKind::kAdapt,   ModelKind::kStages,   ModelKind::kSynthetic};

// "lsystem", "greenlab", "grow", "adapt", "stages", "synthetic".
std::string_view model_kind_name(ModelKind kind);
// The kind of that name, nothing for an unknown one.
std::optional<ModelKind> find_model_kind(std::string_view name);
// "lsystem, greenlab, grow, adapt, stages or synthetic": for messages.
std::string model_kind_names();

}  // namespace fspm::experiments
