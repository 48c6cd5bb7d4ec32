// The active form of FSPM_DCHECK, whatever the build type of the tests.
#undef NDEBUG
#include "fspm/dcheck.hpp"

#include <gtest/gtest.h>

namespace fspm {
namespace {

TEST(DcheckDeathTest, FailedCheckNamesConditionMessageAndPlaceThenAborts) {
  const int lanes = 3;
  EXPECT_DEATH(FSPM_DCHECK(lanes % 2 == 0, "lanes come in pairs"),
               "dcheck_test\\.cpp:[0-9]+: internal check failed: lanes % 2 == 0 \\(lanes come in "
               "pairs\\)");
}

TEST(DcheckDeathTest, PassingCheckDoesNothingAndEvaluatesOnce) {
  int evaluated = 0;
  FSPM_DCHECK(++evaluated == 1, "evaluated once");
  EXPECT_EQ(evaluated, 1);
}

}  // namespace
}  // namespace fspm
