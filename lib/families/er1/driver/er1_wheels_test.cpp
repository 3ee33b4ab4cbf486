// The velocity command as wheel speeds and ports, and counts as travel.
#include "families/er1/driver/er1_wheels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::drivers::er1 {
namespace {

TEST(Er1Wheels, TurningSplitsTheWheelsByTheAxle) {
  const WheelSpeeds wheels = wheel_speeds(100, 30, 0.38);
  const double rotation = 30 * std::numbers::pi / 180 * 190;  // 99.5 mm/s
  EXPECT_NEAR(wheels.left, 100 - rotation, 1e-9);
  EXPECT_NEAR(wheels.right, 100 + rotation, 1e-9);
}

TEST(Er1Wheels, TooFastSlowsBothWheelsAndKeepsTheArc) {
  const WheelSpeeds wheels = wheel_speeds(600, 30, 0.38);
  EXPECT_NEAR(wheels.right, 500, 1e-9);
  const WheelSpeeds asked = {600 - 30 * std::numbers::pi / 180 * 190, 600 + 30 * std::numbers::pi / 180 * 190};
  EXPECT_NEAR(wheels.left / wheels.right, asked.left / asked.right, 1e-9);
  EXPECT_EQ(wheel_speeds(-900, 0, 0.38), (WheelSpeeds{-500, -500}));
}

TEST(Er1Wheels, AReversalIsASignChangeOfEitherWheel) {
  EXPECT_TRUE(reverses({100, 100}, {-100, 100}));
  EXPECT_FALSE(reverses({0, 0}, {-100, -100}));
  EXPECT_FALSE(reverses({100, 100}, {0, 50}));
}

TEST(Er1Wheels, MotorDirPicksThePortOfTheLeftMotor) {
  EXPECT_EQ(Wiring::from_motor_dir(1).left, rcm::Motor::port0);
  EXPECT_EQ(Wiring::from_motor_dir(1).right, rcm::Motor::port1);
  EXPECT_EQ(Wiring::from_motor_dir(-1).left, rcm::Motor::port1);
  EXPECT_EQ(Wiring::from_motor_dir(-1).right, rcm::Motor::port0);
}

TEST(Er1Wheels, TravelFollowsACountAcrossItsWrap) {
  EXPECT_NEAR(wheel_travel(1000, 0), 1000 * 0.00602836879e-3, 1e-12);
  EXPECT_NEAR(wheel_travel(-2147483647 - 1 + 99, 2147483647 - 100), 200 * 0.00602836879e-3, 1e-12);
  EXPECT_NEAR(wheel_travel(-5, 5), -10 * 0.00602836879e-3, 1e-12);
}

}  // namespace
}  // namespace playerkit::drivers::er1
