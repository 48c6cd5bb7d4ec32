// The Release form of FSPM_DCHECK, whatever the build type of the tests.
#ifndef NDEBUG
#define NDEBUG
#endif
#include "fspm/dcheck.hpp"

#include <gtest/gtest.h>

namespace fspm {
namespace {

TEST(DcheckRelease, ConditionIsNotEvaluatedAndNothingFails) {
  int evaluated = 0;
  FSPM_DCHECK(++evaluated < 0, "never true, never evaluated");
  EXPECT_EQ(evaluated, 0);
}

}  // namespace
}  // namespace fspm
