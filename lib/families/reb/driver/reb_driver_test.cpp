// The three reb drivers against the emulated UBot on a real pseudo-terminal:
// the shared line (open on the first device, motors stopped and closed
// after the last), driving and odometry, every control mode and request,
// IR and power, options, and the kit's faults.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <string>

#include "config/errors.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "families/reb/driver/reb_device_driver.hpp"
#include "families/reb/emulator/reb_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/power.hpp"

namespace playerkit::drivers::testing {
namespace reb_driver_test {

using emulators::RebEmulator;
using hardware::reb::Motor;

const std::string kRobot =
    "position:0 ( driver \"reb_position\" port \"$PORT\" $EXTRA )\n"
    "ir:0 ( driver \"reb_ir\" )\n"
    "power:0 ( driver \"reb_power\" )\n";

emulators::FaultPlan faults(std::initializer_list<std::string_view> arguments) {
  emulators::FaultPlan plan;
  for (std::string_view argument : arguments) emulators::add_fault(plan, argument);
  return plan;
}

struct Robot {
  explicit Robot(const std::string& extra = "", LineOptions line = {},
                 emulators::RebEmulatorOptions options = {})
      : board([options] { return std::make_unique<RebEmulator>(options); }, std::move(line)) {
    std::string text = kRobot;
    text.replace(text.find("$EXTRA"), 6, extra);
    devices.load(text, board.port());
  }
  core::Device& position() { return devices.device(protocol::kPositionCode); }
  core::Device& ir() { return devices.device(protocol::kIrCode); }
  core::Device& power() { return devices.device(protocol::kPowerCode); }
  drivers::reb::RebConnection& connection() {
    return dynamic_cast<drivers::reb::RebDeviceDriver&>(position().driver()).connection();
  }
  std::int32_t speed(Motor motor) {
    return board.with([motor](RebEmulator& e) { return e.motor(motor).speed; });
  }
  geometry::Pose2 true_pose() {
    return board.with([](RebEmulator& e) { return e.drive().true_pose(); });
  }
  void motors_on() { ASSERT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{2, 1}))); }
  void drive(std::int32_t xspeed, std::int32_t yawspeed, std::int32_t yaw = 0) {
    write_command(position(), protocol::PositionCommand{.yaw = yaw, .xspeed = xspeed, .yawspeed = yawspeed});
  }

  EmulatedLine<RebEmulator> board;
  ConfiguredDevices devices;
};

TEST(RebSharedLink, OpensOnTheFirstDeviceAndStopsTheMotorsAndClosesAfterTheLast) {
  Robot robot;
  ASSERT_TRUE(robot.ir().subscribe()) << robot.devices.log.all();
  EXPECT_EQ(robot.connection().users(), 1);
  ASSERT_TRUE(robot.board.wait_until([](RebEmulator& e) { return e.ir_on(); }));
  ASSERT_TRUE(robot.position().subscribe());
  ASSERT_TRUE(robot.power().subscribe());
  EXPECT_EQ(robot.connection().users(), 3);
  // The first position subscriber's set-up: the slow UBot's profile of 24.
  EXPECT_TRUE(robot.board.wait_until([](RebEmulator& e) { return e.motor(Motor::left).profile_speed == 24; }));
  robot.motors_on();
  robot.drive(100, 0);
  ASSERT_TRUE(robot.board.wait_until([](RebEmulator& e) {
    return e.motor(Motor::left).speed == 24 && e.motor(Motor::right).speed == -24;
  })) << robot.devices.log.all();
  // The position device leaves while the others stay: the motors stop, the line stays open.
  robot.position().unsubscribe();
  EXPECT_TRUE(robot.board.wait_until(
      [](RebEmulator& e) { return e.motor(Motor::left).speed == 0 && e.motor(Motor::right).speed == 0; }));
  EXPECT_TRUE(more_data(robot.power(), 2));
  robot.ir().unsubscribe();
  EXPECT_TRUE(robot.board.wait_until([](RebEmulator& e) { return !e.ir_on(); }));
  // Moving again, then the last device leaves: stopped, emitters off, closed.
  ASSERT_TRUE(robot.position().subscribe());
  ASSERT_TRUE(robot.ir().subscribe());
  robot.motors_on();
  robot.drive(0, 45);
  ASSERT_TRUE(robot.board.wait_until([](RebEmulator& e) { return e.motor(Motor::left).speed != 0; }));
  robot.position().unsubscribe();
  robot.ir().unsubscribe();
  robot.power().unsubscribe();
  EXPECT_EQ(robot.connection().users(), 0);
  EXPECT_TRUE(robot.board.with([](RebEmulator& e) {
    return e.motor(Motor::left).speed == 0 && e.motor(Motor::right).speed == 0 && !e.ir_on();
  }));
}

TEST(RebPosition, DrivesAsCommandedAndItsOdometryFollowsTheTruePose) {
  Robot robot;
  ASSERT_TRUE(robot.position().subscribe()) << robot.devices.log.all();
  // Motors are off after the first subscription, as 1.5.
  robot.drive(100, 0);
  EXPECT_TRUE(more_data(robot.position(), 3));
  EXPECT_EQ(robot.speed(Motor::left), 0);
  robot.motors_on();
  ASSERT_TRUE(robot.board.wait_until([](RebEmulator& e) { return e.drive().true_pose().x > 0.2; }, 5s));
  robot.drive(0, 0);
  ASSERT_TRUE(robot.board.wait_until([](RebEmulator& e) { return e.motor(Motor::left).speed == 0; }));
  const geometry::Pose2 truth = robot.true_pose();
  const auto data = data_when<protocol::PositionData>(robot.position(), [&](const protocol::PositionData& d) {
    return std::abs(d.xpos - truth.x * 1000.0) < 3.0 && d.xspeed == 0;
  });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->xpos, truth.x * 1000.0, 3.0);
  // The two wheels' set-points go one after the other: under load the robot
  // veers a little at each start and stop, and the odometry with it.
  EXPECT_NEAR(data->ypos, truth.y * 1000.0, 3.0);
  EXPECT_NEAR(truth.y, 0.0, 0.03);
  // Velocities in the interface's units: 100 mm/s is about 100 mm/s (24 pulses / 10 ms = 98.6).
  robot.drive(100, 0);
  const auto moving = data_when<protocol::PositionData>(robot.position(), [](const protocol::PositionData& d) {
    return d.xspeed > 90 && d.xspeed < 110;
  });
  EXPECT_TRUE(moving && moving->xspeed > 90 && moving->xspeed < 110) << (moving ? moving->xspeed : -1);
  // A turn on the spot: the heading follows.
  robot.drive(0, 45);
  const auto turned = data_when<protocol::PositionData>(robot.position(), [](const protocol::PositionData& d) {
    return d.yaw >= 60 && d.yaw < 180;
  });
  ASSERT_TRUE(turned && turned->yaw >= 60) << (turned ? turned->yaw : -1) << robot.devices.log.all();
  robot.drive(0, 0);
}

TEST(RebPosition, RequestsOfTheSheet) {
  Robot robot;
  ASSERT_TRUE(robot.position().subscribe()) << robot.devices.log.all();
  const auto geometry = ask(robot.position(), std::vector<std::uint8_t>{1});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.size[0], 180);
  EXPECT_EQ(geom.size[1], 180);
  EXPECT_TRUE(acked(ask(robot.position(), protocol::PositionSpeedPidRequest{6, 900, 1, 20})));
  EXPECT_TRUE(acked(ask(robot.position(), protocol::PositionPositionPidRequest{7, 150, 0, 10})));
  EXPECT_TRUE(acked(ask(robot.position(), protocol::PositionSpeedProfRequest{8, 200, 100})));
  EXPECT_EQ(robot.board.with([](RebEmulator& e) { return e.motor(Motor::right).profile_speed; }), 49);
  EXPECT_TRUE(acked(ask(robot.position(), protocol::PositionSetOdomRequest{9, 1000, -500, 90})));
  auto data = data_when<protocol::PositionData>(robot.position(), [](const protocol::PositionData& d) {
    return d.xpos == 1000 && d.ypos == -500 && d.yaw == 90;
  });
  EXPECT_TRUE(data && data->yaw == 90);  // theta whole (1.5 took its upper 16 bits)
  EXPECT_TRUE(acked(ask(robot.position(), protocol::PositionResetOdomConfig{4})));
  data = data_when<protocol::PositionData>(robot.position(), [](const protocol::PositionData& d) {
    return d.xpos == 0 && d.ypos == 0 && d.yaw == 0;
  });
  EXPECT_TRUE(data && data->xpos == 0);
  EXPECT_TRUE(nacked(ask(robot.position(), std::vector<std::uint8_t>{42})));   // unknown: NACK (1.5: silence)
  EXPECT_TRUE(nacked(ask(robot.position(), std::vector<std::uint8_t>{2, 1, 0})));  // wrong size: NACK only
}

TEST(RebPosition, PositionModeMovesByTheCommandedDistanceAndReportsArrival) {
  Robot robot;
  ASSERT_TRUE(robot.position().subscribe()) << robot.devices.log.all();
  robot.motors_on();
  ASSERT_TRUE(acked(ask(robot.position(), protocol::PositionPositionModeRequest{5, 1})));
  EXPECT_EQ(robot.connection().control_mode(), drivers::reb::ControlMode::position);
  robot.drive(50, 0);  // a move of 50 mm
  ASSERT_TRUE(robot.board.wait_until([](RebEmulator& e) { return e.motor(Motor::left).target == 1217; }))
      << robot.devices.log.all();
  const auto done = data_when<protocol::PositionData>(
      robot.position(), [](const protocol::PositionData& d) { return d.stall == 1 && d.xpos >= 48; }, 5s);
  ASSERT_TRUE(done && done->stall == 1) << robot.devices.log.all();
  EXPECT_NEAR(done->xpos, 50, 2);
  EXPECT_NEAR(robot.true_pose().x, 0.050, 0.002);
  robot.drive(50, 90);  // the same xspeed and a new yawspeed: a turn of 90 degrees
  const auto turned = data_when<protocol::PositionData>(
      robot.position(), [](const protocol::PositionData& d) { return d.stall == 1 && d.yaw >= 88 && d.yaw <= 92; },
      8s);
  ASSERT_TRUE(turned) << robot.devices.log.all();
  EXPECT_NEAR(robot.true_pose().yaw, std::numbers::pi / 2, 0.03);
  ASSERT_TRUE(acked(ask(robot.position(), protocol::PositionPositionModeRequest{5, 0})));
  EXPECT_EQ(robot.connection().control_mode(), drivers::reb::ControlMode::direct_velocity);
}

TEST(RebPosition, HeadingControlTurnsTowardsTheCommandedYaw) {
  Robot robot("heading_control 1");
  ASSERT_TRUE(robot.position().subscribe()) << robot.devices.log.all();
  EXPECT_TRUE(eventually([&] { return robot.connection().control_mode() == drivers::reb::ControlMode::heading; }));
  robot.motors_on();
  robot.drive(0, 60, 45);
  const auto there = data_when<protocol::PositionData>(
      robot.position(), [](const protocol::PositionData& d) { return d.yaw >= 43 && d.yaw <= 47 && d.yawspeed == 0; },
      8s);
  ASSERT_TRUE(there) << robot.devices.log.all();
  EXPECT_NEAR(robot.true_pose().yaw, std::numbers::pi / 4, 0.05);
  // VELOCITY_MODE 0: velocities as commanded.
  ASSERT_TRUE(acked(ask(robot.position(), protocol::PositionVelocityModeConfig{3, 0})));
  EXPECT_EQ(robot.connection().control_mode(), drivers::reb::ControlMode::direct_velocity);
}

TEST(RebIrAndPower, VoltagesPosesPowerAndTheBatteryInDecivolts) {
  Robot robot;
  ASSERT_TRUE(robot.ir().subscribe()) << robot.devices.log.all();
  ASSERT_TRUE(robot.power().subscribe());
  const auto power = next_data<protocol::PowerData>(robot.power());
  ASSERT_TRUE(power);
  EXPECT_EQ(power->charge, 72);  // 7.2 V (1.5 said 7200)
  const auto ir = next_data<protocol::IrData>(robot.ir());
  ASSERT_TRUE(ir);
  EXPECT_EQ(ir->range_count, 8);
  const auto poses = ask(robot.ir(), std::vector<std::uint8_t>{1});
  ASSERT_TRUE(acked(poses));
  // With its subtype, as the interface says (1.5 left it out).
  const auto pose = protocol::decode<protocol::IrPoseRequest>(poses->payload).poses;
  EXPECT_EQ(pose.pose_count, 8);
  EXPECT_EQ(pose.poses[1], (std::array<std::int16_t, 3>{25, 25, 45}));
  ASSERT_TRUE(acked(ask(robot.ir(), protocol::IrPowerRequest{2, 0})));
  EXPECT_FALSE(robot.board.with([](RebEmulator& e) { return e.ir_on(); }));
  ASSERT_TRUE(acked(ask(robot.ir(), protocol::IrPowerRequest{2, 1})));
  EXPECT_TRUE(robot.board.with([](RebEmulator& e) { return e.ir_on(); }));
  EXPECT_TRUE(nacked(ask(robot.power(), std::vector<std::uint8_t>{1})));
}

TEST(RebOptions, TheFastUbotAndBadValuesAtTheirPlace) {
  // The fast UBot's encoders: 7.92 pulses a mm, 100 mm/s is 8 pulses per 10 ms.
  emulators::RebEmulatorOptions fast_board;
  fast_board.subclass = "fast";
  Robot fast("subclass \"fast\"", {}, fast_board);
  ASSERT_TRUE(fast.position().subscribe()) << fast.devices.log.all();
  EXPECT_EQ(fast.connection().options().subclass, "fast");
  fast.motors_on();
  fast.drive(100, 0);
  EXPECT_TRUE(fast.board.wait_until([](RebEmulator& e) { return e.motor(Motor::left).speed == 8; }));
  ConfiguredDevices bad;
  try {
    bad.load("position:0 ( driver \"reb_position\" heading_control 3 )\n");
    FAIL() << "heading_control 3 was taken";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("1:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("heading_control"), std::string::npos) << e.what();
  }
  ConfiguredDevices differ;
  EXPECT_THROW(differ.load("position:0 ( driver \"reb_position\" port \"/tmp/a\" )\n"
                           "ir:0 ( driver \"reb_ir\" port \"/tmp/b\" )\n"),
               config::ConfigError);
}

class RebLineFaults : public ::testing::TestWithParam<std::string> {};

TEST_P(RebLineFaults, DataKeepsFlowingAndTheLinkCountsWhatItDropped) {
  Robot robot("", LineOptions{.faults = faults({GetParam()})});
  ASSERT_TRUE(robot.position().subscribe()) << robot.devices.log.all();
  ASSERT_TRUE(robot.power().subscribe());
  ASSERT_TRUE(more_data(robot.power(), 20, 20s)) << robot.devices.log.all();
  core::Device& any = robot.position();
  EXPECT_GT(counter(any.driver(), "resyncs") + counter(any.driver(), "timeouts") +
                counter(any.driver(), "missing_prompts") + counter(any.driver(), "stray_lines") +
                counter(any.driver(), "noisy_lines"),
            0u);
  robot.motors_on();
  robot.drive(100, 0);
  EXPECT_TRUE(robot.board.wait_until([](RebEmulator& e) { return e.motor(Motor::left).speed == 24; }));
}

INSTANTIATE_TEST_SUITE_P(Faults, RebLineFaults, ::testing::Values("garbage=0.1", "truncate=0.05", "drop=0.05"),
                         [](const ::testing::TestParamInfo<std::string>& row) {
                           return row.param.substr(0, row.param.find('='));
                         });

TEST(RebFaults, ASilentBoardRefusesTheSubscriptionWithinTheTimeout) {
  Robot robot("", LineOptions{.faults = faults({"silent-start=3"})});
  const auto started = std::chrono::steady_clock::now();
  EXPECT_FALSE(robot.position().subscribe());
  EXPECT_LT(std::chrono::steady_clock::now() - started, 2s);
  EXPECT_EQ(robot.connection().users(), 0);
  EXPECT_EQ(robot.devices.log.count("the board does not answer", core::LogLevel::kError), 1u) << robot.devices.log.all();
}

TEST(RebFaults, ABoardSlowToWakeIsAskedAgainWithinTheSetup) {
  Robot robot("", LineOptions{.faults = faults({"slow-start=0.3"})});
  ASSERT_TRUE(robot.power().subscribe()) << robot.devices.log.all();
  EXPECT_TRUE(more_data(robot.power(), 2));
  EXPECT_GE(counter(robot.power().driver(), "retries"), 1u);
}

TEST(RebFaults, ABoardThatVanishesAndReturnsStopsTheDataThenResumes) {
  Robot robot("", LineOptions{.faults = faults({"vanish=2:2"})});
  ASSERT_TRUE(robot.power().subscribe()) << robot.devices.log.all();
  ASSERT_TRUE(robot.position().subscribe());
  ASSERT_TRUE(acked(ask(robot.position(), protocol::PositionPositionModeRequest{5, 1})));
  ASSERT_TRUE(eventually([&] { return !robot.power().available(); }, 5s)) << robot.devices.log.all();
  EXPECT_FALSE(robot.position().available());
  ASSERT_TRUE(eventually([&] { return robot.power().available(); }, 10s)) << robot.devices.log.all();
  EXPECT_TRUE(more_data(robot.power(), 5));
  EXPECT_TRUE(more_data(robot.position(), 5));
  EXPECT_EQ(counter(robot.power().driver(), "robot_lost"), 1u);
  // The position device's mode outlives the gap; its set-up was sent again.
  EXPECT_EQ(robot.connection().control_mode(), drivers::reb::ControlMode::position);
}

}  // namespace reb_driver_test
}  // namespace playerkit::drivers::testing
