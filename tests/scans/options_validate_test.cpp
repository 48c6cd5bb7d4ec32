// The encoder's and the scan simulator's options check themselves the one way: validate() accepts
// the defaults and throws ValueError whose message names the field out of range.
#include <gtest/gtest.h>

#include <string>

#include "fspm/error.hpp"
#include "scans/cluster_split.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/synthetic_tree.hpp"
#include "tests/validate_refusal.hpp"

namespace fspm::scans {
namespace {

using test_support::refusal;

TEST(OptionsValidate, DefaultsPassAndRefusalsNameTheField) {
  EXPECT_NO_THROW(EncodeOptions{}.validate());
  EXPECT_NO_THROW(ScanOptions{}.validate());

  EncodeOptions encode;
  encode.bin_length_m = -1.0;
  EXPECT_NE(refusal(encode).find("bin_length_m"), std::string::npos) << refusal(encode);
  encode = {};
  encode.root_diameter_m = 0.0;
  EXPECT_NE(refusal(encode).find("root_diameter_m"), std::string::npos) << refusal(encode);

  ScanOptions scan;
  scan.scanners = 0;
  EXPECT_NE(refusal(scan).find("scanners"), std::string::npos) << refusal(scan);
  scan = {};
  scan.range_noise_m = -0.001;
  EXPECT_NE(refusal(scan).find("range_noise_m"), std::string::npos) << refusal(scan);

  SplitOptions split;
  EXPECT_NO_THROW(split.validate());
  split.main_branch_reach = -0.1;
  EXPECT_NE(refusal(split).find("main_branch_reach"), std::string::npos) << refusal(split);

  SyntheticTreeOptions tree;
  EXPECT_NO_THROW(tree.validate());
  tree.twigs = -1;
  EXPECT_NE(refusal(tree).find("twigs"), std::string::npos) << refusal(tree);
}

}  // namespace
}  // namespace fspm::scans
