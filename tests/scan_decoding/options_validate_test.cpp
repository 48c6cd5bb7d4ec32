// The decoding option structs check themselves the one way: validate() accepts the defaults and
// throws ValueError whose message names the field out of range.
#include <gtest/gtest.h>

#include <string>

#include "fspm/error.hpp"
#include "scan_decoding/cluster_texturing.hpp"
#include "scan_decoding/decoding.hpp"
#include "scan_decoding/species_library.hpp"
#include "tests/validate_refusal.hpp"

namespace fspm::scan_decoding {
namespace {

using test_support::refusal;

TEST(OptionsValidate, DefaultsPassAndRefusalsNameTheField) {
  EXPECT_NO_THROW(TextureOptions{}.validate());
  EXPECT_NO_THROW(LibraryOptions{}.validate());
  EXPECT_NO_THROW(DecodeMeshOptions{}.validate());

  TextureOptions texture;
  texture.max_angle_deg = 0.0;
  EXPECT_NE(refusal(texture).find("max_angle_deg"), std::string::npos) << refusal(texture);
  texture = {};
  texture.min_scale_ratio = 1.5;
  EXPECT_NE(refusal(texture).find("min_scale_ratio"), std::string::npos) << refusal(texture);

  LibraryOptions library;
  library.steps = 13;
  EXPECT_NE(refusal(library).find("steps"), std::string::npos) << refusal(library);

  DecodeMeshOptions mesh;
  mesh.prune_distance_m = 0.0;
  EXPECT_NE(refusal(mesh).find("prune_distance_m"), std::string::npos) << refusal(mesh);
}

}  // namespace
}  // namespace fspm::scan_decoding
