#include "interfaces/wire_units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace playerkit::interfaces {
namespace wire_units_test {

TEST(WireUnits, ValuesAreRoundedToTheNearestUnitNotTruncated) {
  EXPECT_EQ(wire_value<std::int32_t>(0.9999 * kMillimetresPerMetre), 1000);
  EXPECT_EQ(wire_value<std::int32_t>(-0.4), 0);
  EXPECT_EQ(wire_value<std::int32_t>(-0.6), -1);
}

TEST(WireUnits, ValuesAreClampedToTheFieldAndNanIsZero) {
  EXPECT_EQ(wire_value<std::int16_t>(40000.0), 32767);
  EXPECT_EQ(wire_value<std::int16_t>(-40000.0), -32768);
  EXPECT_EQ(wire_value<std::uint16_t>(-5.0), 0);
  EXPECT_EQ(wire_value<std::uint32_t>(std::numeric_limits<double>::infinity()), 4294967295u);
  EXPECT_EQ(wire_value<std::int32_t>(std::nan("")), 0);
}

TEST(WireUnits, DegreesAndRadiansAreInverses) {
  EXPECT_DOUBLE_EQ(degrees(std::numbers::pi), 180.0);
  EXPECT_DOUBLE_EQ(radians(90.0), std::numbers::pi / 2);
  EXPECT_NEAR(degrees(radians(37.0)), 37.0, 1e-12);
}

TEST(WireUnits, HeadingsWrapIntoTheChosenRange) {
  EXPECT_EQ(heading_degrees(-std::numbers::pi / 2, HeadingRange::from_0_to_360), 270);
  EXPECT_EQ(heading_degrees(-std::numbers::pi / 2, HeadingRange::from_minus_180_to_180), -90);
  EXPECT_EQ(heading_degrees(std::numbers::pi, HeadingRange::from_minus_180_to_180), 180);
  EXPECT_EQ(heading_degrees(-std::numbers::pi, HeadingRange::from_minus_180_to_180), 180);
  EXPECT_EQ(heading_degrees(radians(359.6), HeadingRange::from_0_to_360), 0);
  EXPECT_EQ(heading_degrees(radians(725.0), HeadingRange::from_0_to_360), 5);
  EXPECT_EQ(heading_degrees(std::numeric_limits<double>::infinity(), HeadingRange::from_0_to_360), 0);
}

}  // namespace wire_units_test
}  // namespace playerkit::interfaces
