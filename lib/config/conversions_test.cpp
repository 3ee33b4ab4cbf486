// Property values convert like C's atoi/atof did in 1.5 (server-behaviour.md §9.3).

#include "config/conversions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace playerkit::config {
namespace conversions_test {

TEST(CAtoi, ReadsLeadingDigitsAndIgnoresTheRest) {
  EXPECT_EQ(c_atoi("42"), 42);
  EXPECT_EQ(c_atoi("12abc"), 12);
  EXPECT_EQ(c_atoi("1.9"), 1);
  EXPECT_EQ(c_atoi("3e5"), 3);
}

TEST(CAtoi, SignsAndLeadingWhitespace) {
  EXPECT_EQ(c_atoi("-5"), -5);
  EXPECT_EQ(c_atoi("+7"), 7);
  EXPECT_EQ(c_atoi(" \t\n 8"), 8);
  EXPECT_EQ(c_atoi("--1"), 0);
  EXPECT_EQ(c_atoi("- 1"), 0);
}

TEST(CAtoi, NoDigitsIsZero) {
  EXPECT_EQ(c_atoi(""), 0);
  EXPECT_EQ(c_atoi("abc"), 0);
  EXPECT_EQ(c_atoi("/dev/ttyS0"), 0);
  EXPECT_EQ(c_atoi("."), 0);
}

TEST(CAtoi, OutOfRangeSaturates) {
  EXPECT_EQ(c_atoi("99999999999999999999"), std::numeric_limits<int>::max());
  EXPECT_EQ(c_atoi("-99999999999999999999"), std::numeric_limits<int>::min());
  EXPECT_EQ(c_atoi("2147483647"), std::numeric_limits<int>::max());
  EXPECT_EQ(c_atoi("-2147483648"), std::numeric_limits<int>::min());
}

TEST(CAtof, ReadsTheLongestNumericPrefix) {
  EXPECT_DOUBLE_EQ(c_atof("0.05"), 0.05);
  EXPECT_DOUBLE_EQ(c_atof("-1.5"), -1.5);
  EXPECT_DOUBLE_EQ(c_atof("+2.5"), 2.5);
  EXPECT_DOUBLE_EQ(c_atof(".5"), 0.5);
  EXPECT_DOUBLE_EQ(c_atof("3."), 3.0);
  EXPECT_DOUBLE_EQ(c_atof("1.2.3"), 1.2);
  EXPECT_DOUBLE_EQ(c_atof("10cm"), 10.0);
  EXPECT_DOUBLE_EQ(c_atof("  7"), 7.0);
}

TEST(CAtof, AcceptsAnExponentInsideAString) {
  // Only a quoted value can hold one: the lexer splits 1e-3 outside quotes.
  EXPECT_DOUBLE_EQ(c_atof("1e-3"), 0.001);
  EXPECT_DOUBLE_EQ(c_atof("2E2"), 200.0);
}

TEST(CAtof, NoNumberIsZero) {
  EXPECT_EQ(c_atof(""), 0.0);
  EXPECT_EQ(c_atof("abc"), 0.0);
  EXPECT_EQ(c_atof("+-1"), 0.0);
  EXPECT_EQ(c_atof("-"), 0.0);
}

TEST(CAtof, OutOfRangeBehavesLikeStrtod) {
  EXPECT_TRUE(std::isinf(c_atof("1e999")));
  EXPECT_GT(c_atof("1e999"), 0.0);
  EXPECT_TRUE(std::isinf(c_atof("-1e999")));
  EXPECT_LT(c_atof("-1e999"), 0.0);
  EXPECT_GE(c_atof("1e-999"), 0.0);
  EXPECT_LT(c_atof("1e-999"), 1e-300);
}

}  // namespace conversions_test
}  // namespace playerkit::config
