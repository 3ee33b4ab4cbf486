// The pose from the wheel counters, and the reference's hacks not copied:
// zero counts integrate, counters wrap, impossible jumps are skipped once.
#include "families/trogdor/driver/wheel_odometry.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "families/trogdor/protocol/trogdor_units.hpp"

namespace playerkit::drivers::trogdor {
namespace {

namespace hw = hardware::trogdor;

std::int32_t ticks(double metres) { return static_cast<std::int32_t>(std::lround(metres / hw::metres_per_tick())); }

TEST(WheelOdometry, StraightAndOnTheSpot) {
  WheelOdometry odometry;
  EXPECT_TRUE(odometry.update({.left_count = 500, .right_count = 500}, 0));
  EXPECT_TRUE(odometry.update({.left_count = 500 + ticks(1.0), .right_count = 500 + ticks(1.0)}, 1.0));
  EXPECT_NEAR(odometry.reported().x, 1.0, 1e-4);
  EXPECT_NEAR(odometry.reported().y, 0.0, 1e-9);
  // A quarter turn on the spot: each wheel pi/4 x axle.
  const double arc = std::numbers::pi / 2 * hw::kAxleLength / 2;
  EXPECT_TRUE(odometry.update({.left_count = 500 + ticks(1.0) - ticks(arc), .right_count = 500 + ticks(1.0) + ticks(arc)},
                              1.0));
  EXPECT_NEAR(odometry.reported().yaw, std::numbers::pi / 2, 1e-3);
  EXPECT_NEAR(odometry.reported().x, 1.0, 1e-4);
}

TEST(WheelOdometry, AZeroCountIsACountAndCountersWrap) {
  WheelOdometry odometry;
  odometry.update({.left_count = -100, .right_count = 2147483600}, 0);
  EXPECT_TRUE(odometry.update({.left_count = 0, .right_count = -2147483596}, 0.1));  // both 100 ticks on
  EXPECT_NEAR(odometry.reported().x, 100 * hw::metres_per_tick(), 1e-9);
  EXPECT_NEAR(odometry.reported().yaw, 0, 1e-9);
}

TEST(WheelOdometry, AnImpossibleJumpIsSkippedAndTheCountersFollowed) {
  WheelOdometry odometry;
  odometry.update({.left_count = 1000, .right_count = 1000}, 0);
  EXPECT_FALSE(odometry.update({.left_count = 1000 + ticks(3.0), .right_count = 1000}, 0.1));
  EXPECT_EQ(odometry.skipped(), 1u);
  EXPECT_TRUE(odometry.update({.left_count = 1000 + ticks(3.1), .right_count = 1000 + ticks(0.1)}, 0.1));
  EXPECT_NEAR(odometry.reported().x, 0.1, 1e-3);
}

TEST(WheelOdometry, RestartKeepsThePose) {
  WheelOdometry odometry;
  odometry.update({.left_count = 1, .right_count = 1}, 0);
  odometry.update({.left_count = 1 + ticks(0.5), .right_count = 1 + ticks(0.5)}, 1);
  odometry.restart();
  EXPECT_TRUE(odometry.update({.left_count = 1'000'000, .right_count = 1'000'000}, 0));
  EXPECT_NEAR(odometry.reported().x, 0.5, 1e-4);
  odometry.update({.left_count = 1'000'000 + ticks(0.5), .right_count = 1'000'000 + ticks(0.5)}, 1);
  EXPECT_NEAR(odometry.reported().x, 1.0, 1e-4);
}

TEST(WheelOdometry, VelocityFromTheReportedWheels) {
  WheelOdometry odometry;
  odometry.update({.left_count = 1, .right_count = 1, .left_velocity = 33, .right_velocity = 33}, 0);
  EXPECT_NEAR(odometry.velocity().x, 0.498, 1e-3);
  EXPECT_EQ(odometry.velocity().yaw, 0);
}

}  // namespace
}  // namespace playerkit::drivers::trogdor
