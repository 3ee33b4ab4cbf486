#include "families/p2os/driver/motor_commands.hpp"

#include <gtest/gtest.h>

#include "families/p2os/protocol/commands.hpp"

namespace playerkit::drivers::p2os {
namespace motor_commands_test {

namespace hw = hardware::p2os;
using Bytes = std::vector<std::uint8_t>;

const hw::RobotParams& p3dx() { return *hw::find_robot_params("Pioneer", "p3dx"); }

hw::Vel2Wheels wheels_of(const hw::Command& command) {
  EXPECT_EQ(command.number, hw::command::vel2);
  return hw::decode_vel2(command.magnitude);
}

TEST(MotorCommands, StraightAheadIsTheSheetsVel2Example) {
  // 100 mm/s on both wheels = 5 units of 20 mm/s: FA FB 06 20 3B 05 05 25 40.
  const auto commands = motor_commands({100, 0}, VelocityMode::direct_wheel, p3dx(), {});
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(hw::command_frame(commands[0]), (Bytes{0xFA, 0xFB, 0x06, 0x20, 0x3B, 0x05, 0x05, 0x25, 0x40}));
}

TEST(MotorCommands, TurningSplitsTheWheelsByTheWheelbase) {
  // 20 deg/s on a p3dx: half the difference = 0.349 rad/s / 0.0056 = 62.3 mm/s.
  const WheelSpeeds speeds = wheel_speeds({300, 20}, p3dx(), {});
  EXPECT_NEAR(speeds.left, 300 - 62.33, 0.01);
  EXPECT_NEAR(speeds.right, 300 + 62.33, 0.01);
  // Rounded to 20 mm/s units: 237.7 -> 12, 362.3 -> 18.
  EXPECT_EQ(wheels_of(vel2_command({300, 20}, p3dx(), {})), (hw::Vel2Wheels{12, 18}));
  EXPECT_EQ(wheels_of(vel2_command({0, -20}, p3dx(), {})), (hw::Vel2Wheels{3, -3}));
}

TEST(MotorCommands, AWheelOverMaxXspeedSlowsBothAndKeepsTheCurve) {
  const MotorLimits limits{.max_xspeed = 400};
  const WheelSpeeds speeds = wheel_speeds({600, 20}, p3dx(), limits);
  EXPECT_NEAR(speeds.right, 400.0, 1e-9);
  EXPECT_NEAR(speeds.left / speeds.right, (600 - 62.33) / (600 + 62.33), 1e-4);
  EXPECT_NEAR(wheel_speeds({-900, 0}, p3dx(), limits).left, -400.0, 1e-9);
}

TEST(MotorCommands, VelBandNeverDrivesTheWheelsAgainstEachOther) {
  const MotorLimits band{.use_vel_band = true};
  // Forward with a sharp turn: the wheel that would go backwards stops.
  WheelSpeeds speeds = wheel_speeds({50, 40}, p3dx(), band);
  EXPECT_EQ(speeds.left, 0.0);
  EXPECT_GT(speeds.right, 0.0);
  // Backward: the wheel that would go forward stops.
  speeds = wheel_speeds({-50, 40}, p3dx(), band);
  EXPECT_LT(speeds.left, 0.0);
  EXPECT_EQ(speeds.right, 0.0);
  // Turning on the spot is not possible at all.
  speeds = wheel_speeds({0, 40}, p3dx(), band);
  EXPECT_EQ(speeds.left, 0.0);
  EXPECT_EQ(speeds.right, 0.0);
  // Without the band it is.
  EXPECT_LT(wheel_speeds({0, 40}, p3dx(), {}).left, 0.0);
}

TEST(MotorCommands, Vel2UnitsAreTheRowsDivisor) {
  // Pioneer 1 rows count VEL2 in 4 mm/s.
  const hw::RobotParams& pion1m = *hw::find_robot_params("Pioneer", "pion1m");
  EXPECT_EQ(wheels_of(vel2_command({100, 0}, pion1m, {})), (hw::Vel2Wheels{25, 25}));
  // A signed byte holds at most 126 units however fast the command.
  EXPECT_EQ(wheels_of(vel2_command({2000, 0}, pion1m, {.max_xspeed = 5000})), (hw::Vel2Wheels{126, 126}));
}

TEST(MotorCommands, SeparateModeSendsVelThenRvelClamped) {
  const MotorLimits limits{.max_xspeed = 500, .max_yawspeed = 30};
  const auto commands = motor_commands({-300, 45}, VelocityMode::separate, p3dx(), limits);
  ASSERT_EQ(commands.size(), 2u);
  // The sheet's VEL -300 example: FA FB 06 0B 1B 2C 01 37 1C.
  EXPECT_EQ(hw::command_frame(commands[0]), (Bytes{0xFA, 0xFB, 0x06, 0x0B, 0x1B, 0x2C, 0x01, 0x37, 0x1C}));
  EXPECT_EQ(commands[1].number, hw::command::rvel);
  EXPECT_EQ(commands[1].value(), 30);
  EXPECT_EQ(motor_commands({900, -45}, VelocityMode::separate, p3dx(), limits)[0].value(), 500);
  EXPECT_EQ(motor_commands({900, -45}, VelocityMode::separate, p3dx(), limits)[1].value(), -30);
}

}  // namespace motor_commands_test
}  // namespace playerkit::drivers::p2os
