// The crown's option structs check themselves the one way: validate() accepts the defaults and
// throws ValueError whose message names the field out of range; CrownOptions checks its parts.
#include <gtest/gtest.h>

#include <string>

#include "crown/crown_from_photo.hpp"
#include "crown/inflation.hpp"
#include "crown/relief.hpp"
#include "fspm/error.hpp"
#include "tests/validate_refusal.hpp"

namespace fspm::crown {
namespace {

using test_support::refusal;

TEST(OptionsValidate, DefaultsPassAndRefusalsNameTheField) {
  EXPECT_NO_THROW(CrownOptions{}.validate());
  CrownOptions crown;
  crown.relief_weight = 2.0;
  EXPECT_NE(refusal(crown).find("relief_weight"), std::string::npos) << refusal(crown);
  crown = {};
  crown.inflation.k = 0.0;  // a part's field, checked with the whole
  EXPECT_NE(refusal(crown).find("k ("), std::string::npos) << refusal(crown);
  crown = {};
  crown.relief.levels = 0;
  EXPECT_NE(refusal(crown).find("levels"), std::string::npos) << refusal(crown);
}

}  // namespace
}  // namespace fspm::crown
