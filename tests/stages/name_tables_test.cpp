// The stages' continuation and growth-profile names both ways, and a misspelled one.
#include <gtest/gtest.h>

#include <string>

#include "fspm/error.hpp"
#include "stages/developmental_model.hpp"
#include "stages/growth_profile.hpp"

namespace fspm::stages {
namespace {

TEST(StagesNames, RoundTrip) {
  for (const auto& e : kContinuationNames.entries()) {
    EXPECT_EQ(continuation_name(e.value), e.name);
    EXPECT_EQ(continuation_from_name(e.name), e.value);
  }
  for (const auto& e : kProfileChoiceNames.entries()) {
    EXPECT_EQ(profile_choice_name(e.value), e.name);
    EXPECT_EQ(profile_choice_from_name(e.name), e.value);
  }
  EXPECT_EQ(continuation_name(Continuation::kThickest), "thickest");
}

TEST(StagesNames, MisspelledContinuation) {
  try {
    continuation_from_name("thickset");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.message(),
              "stages: unknown continuation 'thickset': expected least_deviation or thickest "
              "(did you mean 'thickest'?)");
  }
}

}  // namespace
}  // namespace fspm::stages
