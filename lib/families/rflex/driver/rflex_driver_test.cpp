// The seven rflex devices against the emulated controller on a pty, in 1.5's
// configuration form: the shared link, motion, every request, every sensor.
#include <gtest/gtest.h>

#include <thread>

#include "families/rflex/driver/rflex_test_support.hpp"
#include "protocol/messages/aio.hpp"
#include "protocol/messages/bumper.hpp"
#include "protocol/messages/dio.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers {
namespace rflex_driver_test {

using namespace rflex_testing;

TEST(RflexDriver, OneLineOpenedByTheFirstDeviceAndClosedAfterTheLastWithTheRobotStopped) {
  EmulatedRflex robot;
  RflexDevices devices(robot.port(), b21r_config());
  EXPECT_FALSE(robot.with([](RflexEmulator& e) { return e.reporting_motion(); }));
  ASSERT_TRUE(devices.power().subscribe()) << devices.log.all();
  ASSERT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.reporting_motion(); }));
  ASSERT_TRUE(devices.position().subscribe());
  ASSERT_TRUE(devices.sonar().subscribe());
  ASSERT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.sonar_running(); }));
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 300});
  ASSERT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.translation_command() == 300 * 103; }));

  devices.position().unsubscribe();  // the last position device: stop and brake
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.braked() && e.translation_command() == 0; }));
  devices.sonar().unsubscribe();
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return !e.sonar_running(); }));
  EXPECT_TRUE(robot.with([](RflexEmulator& e) { return e.reporting_motion(); }));  // power still there
  devices.power().unsubscribe();  // the last of all: reports off, line closed
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return !e.reporting_motion(); }));
}

TEST(RflexDriver, DrivesAtTheCommandedSpeedAndIntegratesOdometry) {
  EmulatedRflex robot;
  RflexDevices devices(robot.port(), b21r_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe()) << devices.log.all();
  write_command(position, protocol::PositionCommand{.xspeed = 400});
  const auto moving = data_when<protocol::PositionData>(
      position, [](const protocol::PositionData& d) { return d.xpos > 400; }, 5s);
  ASSERT_TRUE(moving && moving->xpos > 400) << devices.log.all();
  EXPECT_NEAR(moving->xspeed, 400, 2);
  EXPECT_NEAR(moving->ypos, 0, 2);
  write_command(position, protocol::PositionCommand{});
  ASSERT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.translation_command() == 0; }));
  const auto stopped = data_when<protocol::PositionData>(
      position, [](const protocol::PositionData& d) { return d.xspeed == 0; });
  ASSERT_TRUE(stopped && stopped->xspeed == 0);
  ASSERT_TRUE(more_data(position, 2));
  // The odometry is where the robot is (no error configured).
  const auto last = latest<protocol::PositionData>(position);
  EXPECT_NEAR(last->xpos, robot.true_pose().x * 1000.0, 3.0);

  write_command(position, protocol::PositionCommand{.yawspeed = -45});
  const auto turning = data_when<protocol::PositionData>(
      position, [](const protocol::PositionData& d) { return d.yaw > 180 && d.yaw < 330; }, 6s);
  ASSERT_TRUE(turning && turning->yaw < 330 && turning->yaw > 180);
  EXPECT_NEAR(turning->yawspeed, -45, 1);
  write_command(position, protocol::PositionCommand{});
}

TEST(RflexDriver, PositionRequests) {
  EmulatedRflex robot;
  RflexDevices devices(robot.port(), b21r_config());
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe()) << devices.log.all();
  const auto geometry = ask(position, std::vector<std::uint8_t>{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.size[0], 520);
  EXPECT_EQ(geom.size[1], 520);

  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 0})));
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.braked(); }));
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 1})));
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return !e.braked(); }));
  EXPECT_TRUE(acked(ask(position, protocol::PositionVelocityModeConfig{protocol::kPositionVelocityModeReq, 1})));

  // SET_ODOM takes theta whole (1.5 read its upper 16 bits).
  ASSERT_TRUE(acked(ask(position, protocol::PositionSetOdomRequest{protocol::kPositionSetOdomReq, 1000, -2000, 90})));
  const auto set = data_when<protocol::PositionData>(
      position, [](const protocol::PositionData& d) { return d.xpos == 1000; });
  ASSERT_TRUE(set);
  EXPECT_EQ(set->ypos, -2000);
  EXPECT_EQ(set->yaw, 90);
  ASSERT_TRUE(acked(ask(position, protocol::PositionResetOdomConfig{protocol::kPositionResetOdomReq})));
  const auto reset = data_when<protocol::PositionData>(
      position, [](const protocol::PositionData& d) { return d.xpos == 0 && d.yaw == 0; });
  ASSERT_TRUE(reset && reset->xpos == 0 && reset->ypos == 0);
  EXPECT_TRUE(nacked(ask(position, std::vector<std::uint8_t>{protocol::kPositionSpeedPidReq})));
  EXPECT_TRUE(nacked(ask(position, std::vector<std::uint8_t>{protocol::kPositionMotorPowerReq})));  // too short
}

TEST(RflexDriver, SonarRangesInBankOrderAndItsRequests) {
  RflexEmulatorOptions options;
  options.sonar_max_range = 3.0;
  EmulatedRflex robot(options);
  RflexDevices devices(robot.port(), b21r_config());
  core::Device& sonar = devices.sonar();
  ASSERT_TRUE(sonar.subscribe()) << devices.log.all();
  const auto data = data_when<protocol::SonarData>(sonar, [](const protocol::SonarData& d) { return d.ranges[23] > 0; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->range_count, 24);
  for (int i = 0; i < 24; ++i) EXPECT_NEAR(data->ranges[static_cast<std::size_t>(i)], 3000, 2) << i;

  const auto reply = ask(sonar, std::vector<std::uint8_t>{protocol::kSonarGetGeomReq});
  ASSERT_TRUE(acked(reply));
  const auto geom = protocol::decode<protocol::SonarGeom>(reply->payload);
  EXPECT_EQ(geom.pose_count, 24);
  EXPECT_EQ(geom.poses[0], (std::array<std::int16_t, 3>{260, 0, 0}));
  EXPECT_EQ(geom.poses[6][2], 90);  // theta read first, as 1.5 did

  ASSERT_TRUE(acked(ask(sonar, protocol::SonarPowerConfig{protocol::kSonarPowerReq, 0})));
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return !e.sonar_running(); }));
  ASSERT_TRUE(acked(ask(sonar, protocol::SonarPowerConfig{protocol::kSonarPowerReq, 1})));
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.sonar_running(); }));
}

TEST(RflexDriver, InfraredBanksCalibratedAndTheirRequests) {
  EmulatedRflex robot;
  RflexDevices devices(robot.port(), b21r_config());
  core::Device& ir = devices.ir();
  ASSERT_TRUE(ir.subscribe()) << devices.log.all();
  ASSERT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.ir_running(); }));
  const auto data = data_when<protocol::IrData>(ir, [](const protocol::IrData& d) { return d.voltages[0] > 0; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->range_count, 24);
  EXPECT_EQ(data->voltages[0], 250);  // 1 m of open space at 4 mm a count
  EXPECT_EQ(data->ranges[0], 900);    // 1000 mm, clipped to ir_max_range

  const auto reply = ask(ir, std::vector<std::uint8_t>{protocol::kIrPoseReq});
  ASSERT_TRUE(acked(reply));
  const auto poses = protocol::decode<protocol::IrPoseRequest>(reply->payload);
  EXPECT_EQ(poses.poses.pose_count, 24);
  EXPECT_EQ(poses.poses.poses[2], (std::array<std::int16_t, 3>{20, 0, 30}));

  // The 2-byte POWER request (1.5 wanted 1 byte and read a stale state).
  ASSERT_TRUE(acked(ask(ir, protocol::IrPowerRequest{protocol::kIrPowerReq, 0})));
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return !e.ir_running(); }));
  EXPECT_TRUE(nacked(ask(ir, std::vector<std::uint8_t>{protocol::kIrPowerReq})));
}

TEST(RflexDriver, BumperPanelsPowerAndTheEmptyInputs) {
  EmulatedRflex robot;
  RflexDevices devices(robot.port(), b21r_config());
  ASSERT_TRUE(devices.bumper().subscribe()) << devices.log.all();
  ASSERT_TRUE(devices.power().subscribe());
  ASSERT_TRUE(devices.aio().subscribe());
  ASSERT_TRUE(devices.dio().subscribe());
  robot.with([](RflexEmulator& e) {
    e.press_bumper(13, 0x09);
    return 0;
  });
  const auto bumped = data_when<protocol::BumperData>(
      devices.bumper(), [](const protocol::BumperData& d) { return d.bumpers[13] != 0; });
  ASSERT_TRUE(bumped);
  EXPECT_EQ(bumped->bumper_count, 14);
  EXPECT_EQ(bumped->bumpers[13], 0x09);
  const auto reply = ask(devices.bumper(), std::vector<std::uint8_t>{protocol::kBumperGetGeomReq});
  ASSERT_TRUE(acked(reply));
  const auto geom = protocol::decode<protocol::BumperGeom>(reply->payload);
  EXPECT_EQ(geom.bumper_count, 14);
  EXPECT_EQ(geom.bumper_def[2].x_offset, 2);  // 2.7 truncated, as 1.5
  EXPECT_EQ(geom.bumper_def[2].th_offset, 50);
  EXPECT_EQ(geom.bumper_def[2].radius, 260);

  const auto power = next_data<protocol::PowerData>(devices.power());
  ASSERT_TRUE(power);
  EXPECT_EQ(power->charge, 264 + 12);
  EXPECT_TRUE(nacked(ask(devices.power(), std::vector<std::uint8_t>{1})));
  EXPECT_EQ(next_data<protocol::AioData>(devices.aio())->count, 0);
  EXPECT_EQ(next_data<protocol::DioData>(devices.dio())->count, 0);
  EXPECT_TRUE(nacked(ask(devices.dio(), std::vector<std::uint8_t>{1})));
}

TEST(RflexDriver, TheRobotsUnitsComeFromTheConfiguration) {
  RflexEmulatorOptions options;
  options.model = *emulators::rflex::find_rflex_model("atrvjr");
  EmulatedRflex robot(options);
  RflexDevices devices(robot.port(),
                       "position:0 ( driver \"rflex_position\" rflex_serial_port \"$PORT\" "
                       "odo_distance_conversion 90.81 odo_angle_conversion 37000 rflex_done 1 )\n");
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  write_command(devices.position(), protocol::PositionCommand{.xspeed = 200});
  ASSERT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.translation_command() == 18162; }));
  const auto moved = data_when<protocol::PositionData>(
      devices.position(), [](const protocol::PositionData& d) { return d.xpos > 150; });
  ASSERT_TRUE(moved && moved->xpos > 150);
  EXPECT_NEAR(moved->xspeed, 200, 2);
  write_command(devices.position(), protocol::PositionCommand{});
}

TEST(RflexDriver, TheManualsSonarPoseOrderAndOneRobotFromEverySection) {
  EmulatedRflex robot;
  RflexDevices devices(robot.port(),
                       "sonar:0 ( driver \"rflex_sonar\" num_sonars 3 num_sonar_banks 1 num_sonars_in_bank [3] "
                       "sonar_pose_order \"x_y_theta\" mmrad_sonar_poses [100 0 0 0 100 1.5708 -100 0 3.1416] )\n"
                       "power:0 ( driver \"rflex_power\" rflex_serial_port \"$PORT\" rflex_power_offset -4 "
                       "rflex_done 1 )\n");
  ASSERT_TRUE(devices.sonar().subscribe()) << devices.log.all();
  ASSERT_TRUE(devices.power().subscribe());
  const auto reply = ask(devices.sonar(), std::vector<std::uint8_t>{protocol::kSonarGetGeomReq});
  ASSERT_TRUE(acked(reply));
  const auto geom = protocol::decode<protocol::SonarGeom>(reply->payload);
  ASSERT_EQ(geom.pose_count, 3);
  EXPECT_EQ(geom.poses[1], (std::array<std::int16_t, 3>{0, 100, 90}));
  EXPECT_EQ(geom.poses[2], (std::array<std::int16_t, 3>{-100, 0, 180}));
  EXPECT_EQ(next_data<protocol::PowerData>(devices.power())->charge, 264 - 4);
  // Both on the one line written on the power section.
  EXPECT_EQ(devices.counter(devices.sonar(), "motion_reports"), devices.counter(devices.power(), "motion_reports"));
}

TEST(RflexDriver, TheRobotsJoystickDrivesWhileItsButtonIsHeld) {
  EmulatedRflex robot;
  RflexDevices devices(robot.port(), b21r_config("rflex_joystick 1 rflex_joy_pos_ratio 2 rflex_joy_ang_ratio 0"));
  ASSERT_TRUE(devices.position().subscribe()) << devices.log.all();
  robot.with([](RflexEmulator& e) {
    e.hold_joystick({0, 0, 100, 1});  // y 100, button 0 held: 200 mm/s
    return 0;
  });
  EXPECT_TRUE(robot.wait_until([](RflexEmulator& e) { return e.translation_command() == 200 * 103; }));
}

}  // namespace rflex_driver_test
}  // namespace playerkit::drivers
