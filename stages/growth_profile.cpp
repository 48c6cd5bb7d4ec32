#include "stages/growth_profile.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"

namespace fspm::stages {
namespace {

double sigmoid(double x) { return 1.0 / (1.0 + std::exp(-x)); }

// The logistic curve over x in [0, 1], rescaled to run from 0 to 1.
double logistic_share(double x) {
  const double a = kLogisticSteepness;
  const double lo = sigmoid(-0.5 * a), hi = sigmoid(0.5 * a);
  return (sigmoid(a * (x - 0.5)) - lo) / (hi - lo);
}

double logistic_inverse(double share) {
  const double a = kLogisticSteepness;
  const double lo = sigmoid(-0.5 * a), hi = sigmoid(0.5 * a);
  const double y = lo + share * (hi - lo);
  return 0.5 + std::log(y / (1.0 - y)) / a;
}

}  // namespace

std::string_view profile_choice_name(ProfileChoice choice) {
  return kProfileChoiceNames.name(choice);
}

ProfileChoice profile_choice_from_name(std::string_view name) {
  return kProfileChoiceNames.from_name(name, "stages");
}

std::string_view growth_profile_name(GrowthProfile profile) {
  switch (profile) {
    case GrowthProfile::kLogistic:
      return "logistic";
    case GrowthProfile::kAccelerating:
      return "accelerating";
    case GrowthProfile::kConstant:
      break;
  }
  return "constant";
}

double profile_fraction(const ChainProfile& profile, double tau) {
  tau = std::clamp(tau, 0.0, 1.0);
  switch (profile.kind) {
    case GrowthProfile::kAccelerating:
      return std::pow(tau, profile.shape);
    case GrowthProfile::kLogistic:
      return tau >= profile.shape ? 1.0 : logistic_share(tau / profile.shape);
    case GrowthProfile::kConstant:
      break;
  }
  return tau;
}

double profile_time(const ChainProfile& profile, double fraction) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  switch (profile.kind) {
    case GrowthProfile::kAccelerating:
      return std::pow(fraction, 1.0 / profile.shape);
    case GrowthProfile::kLogistic:
      return std::clamp(profile.shape * logistic_inverse(fraction), 0.0, profile.shape);
    case GrowthProfile::kConstant:
      break;
  }
  return fraction;
}

ChainProfile choose_profile(int level, double length_m, double main_length_m, double rate,
                            double level_median_rate, double start) {
  const bool scaffold = level == 1 || length_m >= kScaffoldShare * main_length_m;
  const bool slow = level_median_rate > 0.0 && rate < kSlowChainShare * level_median_rate;
  // A short chain, slow for its level, that started late: a bud that broke late and then grew
  // at its level's pace, so that most of its length comes at the end.
  if (!scaffold && slow && start >= kLateStart) {
    return {GrowthProfile::kAccelerating, kAcceleratingExponent};
  }
  return {};
}

ChainProfile uniform_profile(ProfileChoice choice) {
  switch (choice) {
    case ProfileChoice::kLogistic:
      return {GrowthProfile::kLogistic, 1.0};
    case ProfileChoice::kAccelerating:
      return {GrowthProfile::kAccelerating, kAcceleratingExponent};
    case ProfileChoice::kConstant:
    case ProfileChoice::kByChain:
      break;
  }
  return {};
}

}  // namespace fspm::stages
