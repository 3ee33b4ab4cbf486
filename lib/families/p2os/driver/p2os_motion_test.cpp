// Driving the emulated robot through p2os_position: odometry against the
// controller's own, velocity commands against the kinematics, motor power,
// velocity modes, the clamps, SET_ODOM and RESET_ODOM.
#include <gtest/gtest.h>

#include <cmath>

#include "families/p2os/driver/p2os_test_support.hpp"
#include "families/p2os/driver/robot_readings.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {
namespace p2os_motion_test {

using namespace p2os_testing;
namespace command = hardware::p2os::command;

std::string robot_config(std::string position_options = "") {
  return "position:0 ( driver \"p2os_position\" port \"$PORT\" " + position_options + " )\n";
}

geometry::Pose2 robot_odometry(EmulatedRobot& robot) {
  return robot.with([](P2osRobotEmulator& e) { return e.odometry_pose(); });
}

// Degrees between two headings, in [0, 180].
double degrees_apart(double a_degrees, double b_degrees) {
  return std::abs(std::remainder(a_degrees - b_degrees, 360.0));
}

// Drives with `velocity` until `done`, then stops and waits for the robot to
// stand still and the data to show it.
template <class Done>
void drive_until(core::Device& position, EmulatedRobot& robot, protocol::PositionCommand velocity, Done done) {
  write_command(position, velocity);
  EXPECT_TRUE(eventually(done, 15s));
  write_command(position, protocol::PositionCommand{});
  EXPECT_TRUE(eventually([&] { return robot.wheels_stopped(); }));
  EXPECT_TRUE(more_data(position, 3));
}

void expect_follows(const protocol::PositionData& data, const geometry::Pose2& odometry, double tolerance_mm) {
  EXPECT_NEAR(data.xpos, odometry.x * 1000.0, tolerance_mm);
  EXPECT_NEAR(data.ypos, odometry.y * 1000.0, tolerance_mm);
  EXPECT_LE(degrees_apart(data.yaw, odometry.yaw * 180.0 / 3.14159265358979), 1.0);
}

TEST(P2osMotion, OdometryFollowsTheRobotsOwnOverSeveralMetresAndThe12BitWrap) {
  emulators::P2osEmulatorOptions options;
  // Odometry that is not the truth: the driver must report the robot's
  // odometry, not where the robot really is.
  options.odometry_error.translation_scale = 0.03;
  options.odometry_error.heading_drift_per_metre = 0.02;
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), robot_config("max_xspeed 900"));
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));

  // 2.6 m straight: a p3dx's 12-bit XPOS (0.485 mm per unit) wraps at 1.99 m.
  drive_until(position, robot, {.xspeed = 900}, [&] { return robot_odometry(robot).x > 2.6; });
  auto data = latest<protocol::PositionData>(position);
  ASSERT_TRUE(data);
  EXPECT_GT(data->xpos, 2600) << devices.log.all();
  expect_follows(*data, robot_odometry(robot), 2.0);

  // Then an arc to the left and back towards the start.
  drive_until(position, robot, {.xspeed = 600, .yawspeed = 100},
              [&] { return robot_odometry(robot).yaw > 2.5; });
  drive_until(position, robot, {.xspeed = 900}, [&] { return robot_odometry(robot).x < 1.2; });
  data = latest<protocol::PositionData>(position);
  ASSERT_TRUE(data);
  expect_follows(*data, robot_odometry(robot), 2.0);
  const auto truth = robot.with([](P2osRobotEmulator& e) { return e.true_pose(); });
  EXPECT_GT(std::hypot(truth.x * 1000.0 - data->xpos, truth.y * 1000.0 - data->ypos), 20.0)
      << "the emulator's odometry error should show";
}

TEST(P2osMotion, VelocityCommandsDriveTheWheelsTheKinematicsSay) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  write_command(position, protocol::PositionCommand{.xspeed = 300, .yawspeed = 20});
  // p3dx: half the wheel difference = 20 deg/s / 0.0056 = 62.3 mm/s; in 20 mm/s units 12 and 18.
  ASSERT_TRUE(eventually([&] { return !robot.wheels_stopped(); }));
  const auto wheels = robot.with([](P2osRobotEmulator& e) { return e.wheel_velocities(); });
  EXPECT_NEAR(wheels.left, 0.240, 1e-9);
  EXPECT_NEAR(wheels.right, 0.360, 1e-9);
  const auto data =
      data_when<protocol::PositionData>(position, [](const auto& d) { return d.xspeed == 300; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->xspeed, 300);
  EXPECT_EQ(data->yawspeed, 19);  // (360 - 240) × 0.0056 / 2 rad/s = 19.25 deg/s
  // And the robot turns left while it goes forward.
  ASSERT_TRUE(more_data(position, 10));
  const auto truth = robot.with([](P2osRobotEmulator& e) { return e.true_pose(); });
  EXPECT_GT(truth.x, 0.1);
  EXPECT_GT(truth.y, 0.0);
  EXPECT_GT(truth.yaw, 0.1);
}

TEST(P2osMotion, TheMotorsStayOffUntilMotorPowerAndStopWithIt) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  write_command(position, protocol::PositionCommand{.xspeed = 200});
  ASSERT_TRUE(eventually([&] { return robot.received(command::vel2) >= 5u; }));
  EXPECT_TRUE(robot.wheels_stopped());  // as 1.5: motors off at the first subscription
  EXPECT_FALSE(robot.motors_enabled());

  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  EXPECT_TRUE(eventually([&] { return robot.motors_enabled() && !robot.wheels_stopped(); }));

  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 0})));
  EXPECT_TRUE(eventually([&] { return !robot.motors_enabled() && robot.wheels_stopped(); }));
}

TEST(P2osMotion, SeparateModeSendsVelAndRvel) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  ASSERT_TRUE(acked(ask(position, protocol::PositionVelocityModeConfig{3, 1})));
  write_command(position, protocol::PositionCommand{.xspeed = 250, .yawspeed = 30});
  const auto data = data_when<protocol::PositionData>(
      position, [](const auto& d) { return d.xspeed == 250 && d.yawspeed >= 29; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->xspeed, 250);
  EXPECT_NEAR(data->yawspeed, 30, 1);
  EXPECT_GT(robot.received(command::vel), 0u);
  EXPECT_GT(robot.received(command::rvel), 0u);
  // Back to direct mode: VEL2 again.
  ASSERT_TRUE(acked(ask(position, protocol::PositionVelocityModeConfig{3, 0})));
  const auto vel2_before = robot.received(command::vel2);
  EXPECT_TRUE(eventually([&] { return robot.received(command::vel2) > vel2_before + 2; }));
}

TEST(P2osMotion, MaxXspeedAndMaxYawspeedClampTheCommand) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config("max_xspeed 200 max_yawspeed 10"));
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  write_command(position, protocol::PositionCommand{.xspeed = 800});
  ASSERT_TRUE(eventually([&] { return !robot.wheels_stopped(); }));
  auto wheels = robot.with([](P2osRobotEmulator& e) { return e.wheel_velocities(); });
  EXPECT_NEAR(wheels.left, 0.2, 1e-9);
  EXPECT_NEAR(wheels.right, 0.2, 1e-9);

  ASSERT_TRUE(acked(ask(position, protocol::PositionVelocityModeConfig{3, 1})));
  write_command(position, protocol::PositionCommand{.xspeed = 0, .yawspeed = 90});
  const auto data =
      data_when<protocol::PositionData>(position, [](const auto& d) { return d.xspeed == 0 && d.yawspeed > 5; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->yawspeed, 10, 1);
}

TEST(P2osMotion, SetOdomPlacesTheRobotExactlyAndLaterMotionFollowsIt) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(more_data(position));
  ASSERT_TRUE(acked(ask(position, protocol::PositionSetOdomRequest{9, 1000, 2000, 90})));
  auto data = data_when<protocol::PositionData>(position, [](const auto& d) { return d.xpos == 1000; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->ypos, 2000);
  EXPECT_EQ(data->yaw, 90);

  // Forward is now +y.
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  drive_until(position, robot, {.xspeed = 400}, [&] { return robot_odometry(robot).x > 0.5; });
  data = latest<protocol::PositionData>(position);
  ASSERT_TRUE(data);
  const geometry::Pose2 odometry = robot_odometry(robot);
  EXPECT_NEAR(data->xpos, 1000.0 - odometry.y * 1000.0, 2.0);
  EXPECT_NEAR(data->ypos, 2000.0 + odometry.x * 1000.0, 2.0);
  EXPECT_EQ(data->yaw, 90);

  // A negative heading is the heading (1.5 made it 65535).
  ASSERT_TRUE(acked(ask(position, protocol::PositionSetOdomRequest{9, 0, 0, -45})));
  data = data_when<protocol::PositionData>(position, [](const auto& d) { return d.xpos == 0; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->yaw, 315);
}

TEST(P2osMotion, ResetOdomZeroesTheRobotAndTheReport) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  drive_until(position, robot, {.xspeed = 400, .yawspeed = 20}, [&] { return robot_odometry(robot).x > 0.4; });

  const auto resets_before = robot.received(command::seto);
  ASSERT_TRUE(acked(ask(position, std::vector<std::uint8_t>{protocol::kPositionResetOdomReq})));
  EXPECT_TRUE(eventually([&] { return robot.received(command::seto) == resets_before + 1; }));
  ASSERT_TRUE(more_data(position, 3));
  auto data = latest<protocol::PositionData>(position);
  ASSERT_TRUE(data);
  EXPECT_EQ(data->xpos, 0);
  EXPECT_EQ(data->ypos, 0);
  EXPECT_EQ(data->yaw, 0);
  // The robot's counters restarted too; the report goes on with them.
  drive_until(position, robot, {.xspeed = 400}, [&] { return robot_odometry(robot).x > 0.3; });
  data = latest<protocol::PositionData>(position);
  ASSERT_TRUE(data);
  expect_follows(*data, robot_odometry(robot), 2.0);
}

TEST(P2osMotion, ResetOdomWhileDrivingStaysContinuous) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), robot_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe());
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  write_command(position, protocol::PositionCommand{.xspeed = 500});
  ASSERT_TRUE(eventually([&] { return robot_odometry(robot).x > 0.3; }));
  ASSERT_TRUE(acked(ask(position, std::vector<std::uint8_t>{protocol::kPositionResetOdomReq})));
  drive_until(position, robot, {.xspeed = 500}, [&] { return robot_odometry(robot).x > 0.5; });
  const auto data = latest<protocol::PositionData>(position);
  ASSERT_TRUE(data);
  // The report restarted where the robot obeyed SETO, give or take one SIP
  // period of motion (50 mm at 0.5 m/s), and never jumped back by the
  // distance driven before.
  expect_follows(*data, robot_odometry(robot), 60.0);
}

}  // namespace p2os_motion_test
}  // namespace playerkit::drivers
