// Connecting: several rows of the parameter table, the speed found by
// probing, TCP instead of a serial line, and the options that change the
// start-up.
#include <gtest/gtest.h>

#include "families/p2os/driver/p2os_test_support.hpp"
#include "families/p2os/driver/robot_readings.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "links/serial_link.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers {
namespace p2os_handshake_test {

using namespace p2os_testing;
namespace command = hardware::p2os::command;

constexpr std::string_view kRobot =
    "position:0 ( driver \"p2os_position\" port \"$PORT\" )\n"
    "sonar:0 ( driver \"p2os_sonar\" )\n";

struct Model {
  std::string subclass;
  int sonars;
  std::array<std::int16_t, 3> first_pose;
};

class P2osModels : public ::testing::TestWithParam<Model> {};

TEST_P(P2osModels, TheRowComesFromTheRobotsOwnSubclass) {
  const Model& model = GetParam();
  emulators::P2osEmulatorOptions options;
  options.subclass = model.subclass;
  options.robot_name = "robot-" + model.subclass;
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.sonar().subscribe()) << devices.log.all();

  const auto identity = devices.connection(devices.sonar()).identity();
  ASSERT_TRUE(identity);
  EXPECT_EQ(identity->name, "robot-" + model.subclass);
  EXPECT_EQ(identity->robot_class, "Pioneer");
  EXPECT_EQ(identity->subclass, model.subclass);

  const auto sonar = data_when<protocol::SonarData>(devices.sonar(), [](const auto& d) { return d.ranges[0] > 0; });
  ASSERT_TRUE(sonar);
  EXPECT_EQ(sonar->range_count, model.sonars);
  const auto reply = ask(devices.sonar(), std::vector<std::uint8_t>{protocol::kSonarGetGeomReq});
  ASSERT_TRUE(acked(reply));
  const auto geometry = protocol::decode<protocol::SonarGeom>(reply->payload);
  EXPECT_EQ(geometry.pose_count, model.sonars);
  EXPECT_EQ(geometry.poses[0], model.first_pose);
  EXPECT_EQ(geometry.poses[static_cast<std::size_t>(model.sonars)], (std::array<std::int16_t, 3>{}));
}

INSTANTIATE_TEST_SUITE_P(
    TableRows, P2osModels,
    ::testing::Values(Model{"p3dx", 16, {115, 130, 90}}, Model{"p2at", 16, {145, 130, 90}},
                      Model{"amigo", 8, {73, 105, 90}}, Model{"p2pb", 24, {115, 130, 90}},
                      // The sheet gives no poses for the Pioneer 1 rows: zeros.
                      Model{"pion1m", 7, {0, 0, 0}}),
    [](const ::testing::TestParamInfo<Model>& row) { return row.param.subclass; });

TEST(P2osHandshake, APioneer1DrivesWithItsOwnUnits) {
  // 4 mm/s VEL2 units, 1024 heading units per turn, 0.05066 mm position units.
  emulators::P2osEmulatorOptions options;
  options.subclass = "pion1m";
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 200, .yawspeed = 10});
  ASSERT_TRUE(eventually([&] { return !robot.wheels_stopped(); }));
  const auto wheels = robot.with([](P2osRobotEmulator& e) { return e.wheel_velocities(); });
  // 10 deg/s / 0.0033 = 52.9 mm/s each way; in 4 mm/s units: 37 and 63.
  EXPECT_NEAR(wheels.left, 0.148, 1e-9);
  EXPECT_NEAR(wheels.right, 0.252, 1e-9);
  ASSERT_TRUE(more_data(devices.position(), 10));
  const auto odometry = robot.with([](P2osRobotEmulator& e) { return e.odometry_pose(); });
  const auto data = latest<protocol::PositionData>(devices.position());
  ASSERT_TRUE(data);
  // A SIP period of motion at most between the two reads (25 mm, 2 degrees).
  EXPECT_NEAR(data->xpos, odometry.x * 1000.0, 30.0);
  EXPECT_NEAR(data->yaw, p2os::whole_degrees(odometry.yaw), 3.0);
}

class P2osAutoBaud : public ::testing::TestWithParam<int> {};

TEST_P(P2osAutoBaud, TheRobotsSpeedIsFoundByTryingTheSheetsList) {
  emulators::P2osEmulatorOptions options;
  options.model_baud = GetParam();  // bytes at any other speed are noise to it
  EmulatedRobot robot(options);
  RobotDevices devices(robot.port(), std::string(kRobot) + "");
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  EXPECT_EQ(devices.connection(devices.position()).baud(), GetParam());
  EXPECT_TRUE(more_data(devices.position(), 3));
  EXPECT_EQ(devices.log.count(", " + std::to_string(GetParam()) + " baud)"), 1u) << devices.log.all();
}

INSTANTIATE_TEST_SUITE_P(Speeds, P2osAutoBaud, ::testing::Values(9600, 38400, 57600));

TEST(P2osHandshake, ARobotStillStreamingFromAnEarlierSessionIsClosedFirst) {
  EmulatedRobot robot;
  // An earlier program opened the robot and still holds the port (shared,
  // not exclusive), so the robot keeps streaming SIPs.
  links::SerialSettings shared;
  shared.exclusive = false;
  auto earlier = links::SerialLink::open(robot.port(), shared);
  std::vector<std::uint8_t> handshake;
  for (const std::uint8_t number : {command::sync0, command::sync1, command::sync2, command::open}) {
    const auto frame = hardware::p2os::command_frame(hardware::p2os::Command::plain(number));
    handshake.insert(handshake.end(), frame.begin(), frame.end());
  }
  earlier->write_all(handshake, links::deadline_in(1s));
  ASSERT_TRUE(eventually([&] { return robot.connected(); }));

  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.sonar().subscribe()) << devices.log.all();
  // Command 2: the earlier SYNC2, our CLOSE, our SYNC2.
  EXPECT_EQ(robot.received(command::close), 3u);
  EXPECT_TRUE(more_data(devices.sonar(), 3));
}

TEST(P2osHandshake, OverTcpAsThroughASerialBridge) {
  EmulatedRobot robot({}, {}, /*over_tcp=*/true);
  ASSERT_EQ(robot.port().rfind("tcp:127.0.0.1:", 0), 0u) << robot.port();
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  EXPECT_EQ(devices.connection(devices.position()).baud(), 0);  // no line speed to probe
  ASSERT_TRUE(acked(ask(devices.position(), protocol::PositionPowerConfig{2, 1})));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 300});
  const auto moving = data_when<protocol::PositionData>(devices.position(),
                                                        [](const auto& d) { return d.xpos > 50; });
  ASSERT_TRUE(moving);
  EXPECT_GT(moving->xpos, 50);
  EXPECT_EQ(moving->xspeed, 300);
  devices.position().unsubscribe();
  EXPECT_TRUE(eventually([&] { return robot.wheels_stopped() && !robot.motors_enabled(); }));
}

TEST(P2osHandshake, JoystickOptionLetsTheJoystickDrive) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(),
                       "position:0 ( driver \"p2os_position\" port \"$PORT\" )\n"
                       "sonar:0 ( driver \"p2os_sonar\" joystick 1 )\n");
  ASSERT_TRUE(devices.sonar().subscribe());
  EXPECT_TRUE(eventually([&] { return robot.received(command::joydrive) == 1u; }));
}

TEST(P2osHandshake, RadioModemDialFirstThenSynchronise) {
  // The emulator is a robot on a plain line: no modem answers the dial, so
  // after the 3.4 s 1.5 waited there is one warning and the handshake goes on.
  EmulatedRobot robot;
  RobotDevices devices(robot.port(),
                       "position:0 ( driver \"p2os_position\" port \"$PORT\" radio 1 connect_timeout 8 )\n");
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  EXPECT_EQ(devices.log.count("the radio modem did not report a connection", core::LogLevel::kWarning), 1u);
  // "WMS2\r" reached the robot first, as line noise to it.
  EXPECT_GE(robot.with([](P2osRobotEmulator& e) { return e.counters().noise_bytes; }), 5u);
  EXPECT_TRUE(more_data(devices.position()));
}

TEST(P2osHandshake, NoJoystickDriveByDefault) {
  EmulatedRobot robot;
  RobotDevices devices(robot.port(), std::string(kRobot));
  ASSERT_TRUE(devices.sonar().subscribe());
  ASSERT_TRUE(more_data(devices.sonar(), 3));
  EXPECT_EQ(robot.received(command::joydrive), 0u);
}

}  // namespace p2os_handshake_test
}  // namespace playerkit::drivers
