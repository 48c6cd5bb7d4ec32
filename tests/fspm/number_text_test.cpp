#include "fspm/number_text.hpp"
#include "fspm/p_value_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fspm {
namespace {

// Values quoted from human output that printed every binary digit; the expected text is the
// value rounded by hand to four significant digits.
TEST(FormatSignificant, RoundsToFourSignificantDigits) {
  EXPECT_EQ(format_significant(5.190458949999998), "5.19");
  EXPECT_EQ(format_significant(5.4799999999999995), "5.48");
  EXPECT_EQ(format_significant(452.61), "452.6");
  EXPECT_EQ(format_significant(0.012345), "0.01235");
  EXPECT_EQ(format_significant(-2.71828), "-2.718");
  EXPECT_EQ(format_significant(5.19, 2), "5.2");
}

TEST(FormatSignificant, DropsTrailingZerosAndKeepsIntegers) {
  EXPECT_EQ(format_significant(12.0), "12");
  EXPECT_EQ(format_significant(0.5), "0.5");
  EXPECT_EQ(format_significant(6059.0), "6059");
  // Integer digits are never cut: a count stays a count.
  EXPECT_EQ(format_significant(123456.0), "123456");
  EXPECT_EQ(format_significant(12345.6), "12346");
  EXPECT_EQ(format_significant(9.99995), "10");
}

TEST(FormatSignificant, SmallAndHugeValuesUseAnExponent) {
  EXPECT_EQ(format_significant(1.2345e-5), "1.234e-05");
  EXPECT_EQ(format_significant(-3.0e-7), "-3e-07");
  EXPECT_EQ(format_significant(2.5e16), "2.5e+16");
}

TEST(FormatSignificant, RoundingNoiseIsZero) {
  EXPECT_EQ(format_significant(-3.18e-18), "0");
  EXPECT_EQ(format_significant(0.0), "0");
  EXPECT_EQ(format_significant(-0.0), "0");
}

TEST(FormatSignificant, NonFiniteValuesAreNamed) {
  EXPECT_EQ(format_significant(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_significant(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_significant(-std::numeric_limits<double>::infinity()), "-inf");
}

// Never more than four significant digits, whatever the value (an integer part excepted).
TEST(FormatSignificant, NeverMoreThanFourSignificantDigitsBelowTenThousand) {
  for (double v = 1e-4; v < 1e4; v *= 1.0137) {
    const std::string text = format_significant(v);
    if (text.find('e') != std::string::npos) continue;
    int significant = 0;
    bool started = false;
    for (char c : text) {
      if (c >= '1' && c <= '9') started = true;
      if (started && c >= '0' && c <= '9') ++significant;
    }
    EXPECT_LE(significant, 4) << text;
    EXPECT_NEAR(*parse_number(text), v, v * 5e-4) << text;
  }
}

// A p value far below the noise floor of format_significant is a strong result, not zero: the
// printed line says "p < 0.001" as journals do (APA), never "p = 0".
TEST(FormatPValue, TinyPValuesAreBelowAThousandthNotZero) {
  EXPECT_EQ(format_p_value(3.4e-15), "p < 0.001");
  EXPECT_EQ(format_p_value(0.0), "p < 0.001");
  EXPECT_EQ(format_p_value(0.0479414), "p = 0.048");
  EXPECT_EQ(format_p_value(0.0016), "p = 0.0016");
  EXPECT_EQ(format_p_value(1.0), "p = 1");
  EXPECT_EQ(format_p_value(std::nan("")), "p undefined");
}

}  // namespace
}  // namespace fspm
