#pragma once
// Growth-rate profiles of the chains of a developmental model (Pirk 2013, 5.3.1). Eq. 5.3 gives
// every chain a constant rate that completes it at t = 1; Pirk names logistic and accelerating
// growth as alternatives. A profile maps a chain's own time tau in [0, 1] (0 at its start, 1 at
// t = 1) to the share of its length grown by then, f(0) = 0, f(1) = 1, never decreasing.
//   - constant:     f = tau (eq. 5.3).
//   - accelerating: f = tau^k, k > 1 (slow first, fast last; the early part of the growth curves
//                   of Richards 1959).
//   - logistic:     an S-curve (Verhulst 1838) over [0, tau_end], complete at tau_end <= 1.
#include <cstdint>
#include <string_view>

#include "fspm/name_table.hpp"

namespace fspm::stages {

enum class GrowthProfile : std::uint8_t { kConstant, kLogistic, kAccelerating };

// How the chains get their profiles.
enum class ProfileChoice : std::uint8_t {
  kConstant,      // Pirk eq. 5.3 for every chain
  kByChain,       // from each chain's length, order and start (choose_profile)
  kLogistic,      // every chain an S-curve over its whole span (tau_end = 1)
  kAccelerating,  // every chain tau^k
};
inline constexpr NameTable<ProfileChoice, 4> kProfileChoiceNames{
    "growth profile choice",
    {{ProfileChoice::kConstant, "constant", "eq. 5.3 for every chain"},
     {ProfileChoice::kByChain, "by_chain",
      "accelerating for short slow chains that start late, constant for the others"},
     {ProfileChoice::kLogistic, "logistic", "every chain an S-curve"},
     {ProfileChoice::kAccelerating, "accelerating", "every chain tau^k"}}};
inline constexpr auto kProfileChoices = kProfileChoiceNames.values();

// "constant", "by_chain", "logistic", "accelerating".
std::string_view profile_choice_name(ProfileChoice choice);
// Throws ValueError naming the known names (and the closest one) for anything else.
ProfileChoice profile_choice_from_name(std::string_view name);
// "constant", "logistic", "accelerating".
std::string_view growth_profile_name(GrowthProfile profile);

struct ChainProfile {
  GrowthProfile kind = GrowthProfile::kConstant;
  double shape = 1.0;  // k of the accelerating profile, tau_end of the logistic one
};

// Steepness of the logistic S-curve over its span: the curve of 1 / (1 + e^-a(x - 1/2)),
// rescaled to run from 0 to 1 over x in [0, 1], with a = 8 (1.8 % of the length in the first and
// the last tenth of the span).
inline constexpr double kLogisticSteepness = 8.0;
// k of the accelerating profile.
inline constexpr double kAcceleratingExponent = 2.0;
// A chain whose constant rate of eq. 5.3 is below this share of the median rate of its level is
// slow for its level.
inline constexpr double kSlowChainShare = 0.5;
// A chain at least this share of the main chain's length is a scaffold axis.
inline constexpr double kScaffoldShare = 0.25;
// A slow chain starting at or after this time is a late bud.
inline constexpr double kLateStart = 0.5;

// The share of the chain grown at its own time tau (clamped to [0, 1]).
double profile_fraction(const ChainProfile& profile, double tau);
// The own time at which the chain has grown `fraction` (in [0, 1]) of its length.
double profile_time(const ChainProfile& profile, double fraction);

// The profile of a chain of `level` (1: the main chain) and `length_m` starting at `start`,
// whose constant rate of eq. 5.3 is `rate` against the median `level_median_rate` of its level's
// chains, on a tree whose main chain is `main_length_m` long: accelerating for a short chain
// (under kScaffoldShare of the main chain) slower than kSlowChainShare of its level's median that
// starts at or after kLateStart (a bud that broke late; on grown trees of known history these
// chains appear later than eq. 5.3 has them, docs/stages.md); constant (eq. 5.3) for all others,
// the main chain and scaffold axes among them (the height of the grown trees is close to linear
// in time).
ChainProfile choose_profile(int level, double length_m, double main_length_m, double rate,
                            double level_median_rate, double start);
// The profile of every chain for a uniform choice (constant for kByChain).
ChainProfile uniform_profile(ProfileChoice choice);

}  // namespace fspm::stages
