#include "families/ptu46/protocol/ptu_units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace playerkit::hardware::ptu46 {
namespace {

// ptu46.md §2.2's worked example, the PTU-46-17.5 at 185.1428" a position.
TEST(PtuUnits, TheSheetsWorkedExample) {
  const double resolution = degrees_per_position(185.1428);
  EXPECT_NEAR(resolution, 0.0514286, 1e-7);
  EXPECT_EQ(positions_from_degrees(30, resolution), 583);
  EXPECT_EQ(std::lround(degrees_from_positions(583, resolution)), 30);
  EXPECT_EQ(positions_from_degrees(50, resolution), 972);
  EXPECT_EQ(std::lround(degrees_from_positions(1000, resolution)), 51);
}

TEST(PtuUnits, DemandsTruncateTowardZero) {
  const double resolution = degrees_per_position(185.1428);
  EXPECT_EQ(positions_from_degrees(-30, resolution), -583);
  EXPECT_EQ(positions_from_degrees(0.05, resolution), 0);
}

TEST(PtuUnits, AResolutionThatIsNotPositiveConvertsNothing) {
  EXPECT_EQ(degrees_per_position(0), 0);
  EXPECT_EQ(degrees_per_position(-5), 0);
  EXPECT_EQ(positions_from_degrees(30, 0), 0);
  EXPECT_EQ(positions_from_degrees(NAN, 0.05), 0);
}

}  // namespace
}  // namespace playerkit::hardware::ptu46
