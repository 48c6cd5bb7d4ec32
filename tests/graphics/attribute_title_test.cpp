#include "graphics/attribute_title.hpp"

#include <gtest/gtest.h>

namespace fspm::graphics {
namespace {

// The attributes fspm writes carry their meaning and unit in a legend; others keep their name.
TEST(AttributeTitle, SaysWhatTheValuesMean) {
  EXPECT_EQ(attribute_title("light"), "light\nshare of the\nopen sky");
  EXPECT_NE(attribute_title("displacement").find("(m)"), std::string::npos);
  EXPECT_EQ(attribute_title("order"), "order");
  EXPECT_EQ(attribute_title(""), "");
}

}  // namespace
}  // namespace fspm::graphics
