// The trogdor driver against the emulated robot on a real pseudo-terminal,
// through the kit's driver harness: the start-up of trogdor.md §2, commands
// as wheel units, odometry as position data, every request, bad options,
// and each fault of the kit.

#include "families/trogdor/driver/trogdor_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/trogdor/driver/trogdor_options.hpp"
#include "families/trogdor/emulator/trogdor_emulator.hpp"
#include "families/trogdor/protocol/trogdor_units.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace {

using emulators::TrogdorEmulator;
namespace hw = hardware::trogdor;

struct TrogdorDriverTest : ::testing::Test {
  explicit TrogdorDriverTest(LineOptions options = {})
      : robot([] { return std::make_unique<TrogdorEmulator>(emulators::TrogdorEmulatorOptions{}, nullptr); },
              std::move(options)) {}

  core::Device& position() { return devices.device(protocol::kPositionCode); }
  void start() {
    devices.load("position:0 ( driver \"trogdor\" port \"$PORT\" )\n", robot.port());
    ASSERT_TRUE(position().subscribe()) << devices.log.all();
  }

  EmulatedLine<TrogdorEmulator> robot;
  ConfiguredDevices devices;
};

TEST_F(TrogdorDriverTest, StartsTheRobotAsPlayerDidAndPublishesItsPose) {
  start();
  EXPECT_TRUE(robot.with([](TrogdorEmulator& e) { return e.initialised(); }));
  EXPECT_EQ(robot.with([](TrogdorEmulator& e) { return e.accelerations(); }), (hw::WheelPair{10, 10}));
  const auto data = next_data<protocol::PositionData>(position());
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_EQ(data->xpos, 0);
  EXPECT_EQ(data->ypos, 0);
  EXPECT_EQ(data->yaw, 0);
  EXPECT_EQ(data->stall, 0);
}

TEST_F(TrogdorDriverTest, DrivesWhereTheClientSaysAndReportsWhereItGot) {
  start();
  write_command(position(), protocol::PositionCommand{.xspeed = 500, .yawspeed = 0});
  ASSERT_TRUE(robot.wait_until([](TrogdorEmulator& e) { return e.velocities() == hw::WheelPair{33, 33}; }))
      << devices.log.all();
  const auto moving = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 300; });
  ASSERT_TRUE(moving) << devices.log.all();
  EXPECT_EQ(moving->xspeed, 498);  // 33 units
  EXPECT_EQ(moving->yawspeed, 0);
  write_command(position(), protocol::PositionCommand{.xspeed = 0, .yawspeed = 90});
  ASSERT_TRUE(robot.wait_until([](TrogdorEmulator& e) { return e.velocities() == hw::WheelPair{-16, 16}; }));
  const auto turning = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.yaw >= 45 && d.yaw < 180; });
  ASSERT_TRUE(turning) << devices.log.all();
  EXPECT_EQ(turning->yawspeed, 87);  // 16 units a wheel
  write_command(position(), protocol::PositionCommand{});
  ASSERT_TRUE(robot.wait_until([](TrogdorEmulator& e) { return e.velocities() == hw::WheelPair{0, 0}; }));
  // The reported pose is the emulator's odometry (exact here) to the millimetre and degree.
  const auto still = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xspeed == 0; });
  ASSERT_TRUE(still);
  const auto truth = robot.with([](TrogdorEmulator& e) { return e.drive().odometry(); });
  EXPECT_NEAR(still->xpos, truth.x * 1000, 2);
  EXPECT_NEAR(still->ypos, truth.y * 1000, 2);
  EXPECT_NEAR(still->yaw, std::fmod(truth.yaw * 180 / M_PI + 360, 360), 1.5);
}

TEST_F(TrogdorDriverTest, AnswersEveryRequestOfThePositionInterface) {
  start();
  const auto geometry = ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.size[0], 450);
  EXPECT_EQ(geom.size[1], 450);
  EXPECT_EQ(geom.pose[0], 0);

  EXPECT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq, .value = 0})));
  EXPECT_FALSE(robot.with([](TrogdorEmulator& e) { return e.motion_enabled(); }));
  EXPECT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq, .value = 1})));
  EXPECT_TRUE(robot.with([](TrogdorEmulator& e) { return e.motion_enabled(); }));

  EXPECT_TRUE(acked(ask(position(), protocol::PositionSetOdomRequest{.subtype = protocol::kPositionSetOdomReq,
                                                                     .x = 1000, .y = -500, .theta = 90})));
  auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos == 1000; });
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_EQ(data->ypos, -500);
  EXPECT_EQ(data->yaw, 90);
  EXPECT_TRUE(acked(ask(position(), protocol::PositionResetOdomConfig{.request = protocol::kPositionResetOdomReq})));
  data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos == 0 && d.yaw == 0; });
  ASSERT_TRUE(data);
  EXPECT_TRUE(nacked(ask(position(), std::vector<std::uint8_t>{protocol::kPositionSpeedPidReq, 0})));
  EXPECT_TRUE(nacked(ask(position(), std::vector<std::uint8_t>{77})));
}

TEST_F(TrogdorDriverTest, StopsAndReleasesTheRobotAtTheLastUnsubscription) {
  start();
  write_command(position(), protocol::PositionCommand{.xspeed = 200});
  ASSERT_TRUE(robot.wait_until([](TrogdorEmulator& e) { return e.velocities().left > 0; }));
  position().unsubscribe();
  EXPECT_TRUE(robot.wait_until([](TrogdorEmulator& e) { return e.velocities() == hw::WheelPair{} && !e.initialised(); }));
}

TEST(TrogdorOptions, ThePortIsCheckedAtItsPlace) {
  const std::string error = config_error_of("position:0 ( driver \"trogdor\" port \"tcp:localhost\" )\n");
  EXPECT_NE(error.find(":1:36: trogdor: port is not a serial port"), std::string::npos) << error;
}

// The README's options table is the schema's own.
TEST(TrogdorOptions, TheReadmeTableIsTheSchemas) {
  EXPECT_EQ(readme_options_table(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/trogdor/README.md",
                                 "trogdor"),
            trogdor::trogdor_option_schema().markdown());
}

TEST_F(TrogdorDriverTest, RefusesTheSubscriptionWhenNothingAnswers) {
  robot.replug(false);
  devices.load("position:0 ( driver \"trogdor\" port \"" + robot.port() + "\" )\n");
  EXPECT_FALSE(position().subscribe());
}

struct TrogdorReplugTest : TrogdorDriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("trogdor-replug");
    return {.tcp = false, .symlink = scratch.file("ttyTrogdor"), .faults = {}};
  }
  TrogdorReplugTest() : TrogdorDriverTest(on_a_symlink()) {}
};

// A new robot's counters start afresh: the pose carries on where it was.
TEST_F(TrogdorReplugTest, ARobotUnpluggedAndBackIsFoundAgain) {
  start();
  ASSERT_TRUE(acked(ask(position(), protocol::PositionSetOdomRequest{.subtype = protocol::kPositionSetOdomReq,
                                                                     .x = 700, .y = 0, .theta = 0})));
  ASSERT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos == 700; }));
  robot.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the Trogdor"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(position(), 2)) << devices.log.all();
  EXPECT_EQ(latest<protocol::PositionData>(position())->xpos, 700);
  EXPECT_TRUE(robot.with([](TrogdorEmulator& e) { return e.initialised(); }));
}

struct TrogdorFaultTest : TrogdorDriverTest {
  explicit TrogdorFaultTest(emulators::FaultPlan plan) : TrogdorDriverTest({.tcp = false, .symlink = {}, .faults = plan}) {}
};

struct TrogdorSilentSpellTest : TrogdorFaultTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan plan;
    plan.vanish_at = std::chrono::seconds(1);
    plan.vanish_for = std::chrono::seconds(2);
    return plan;
  }
  TrogdorSilentSpellTest() : TrogdorFaultTest(plan()) {}
};

// The line dies both ways for a while: data stops, the robot is lost with
// a clear reason, and it is started again when it answers.
TEST_F(TrogdorSilentSpellTest, ARobotThatFallsSilentIsLostAndFoundAgain) {
  start();
  EXPECT_FALSE(devices.log.first_with({"lost the Trogdor", "no reply"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(position().available());
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(position(), 2)) << devices.log.all();
  EXPECT_EQ(counter(position().driver(), "reconnects"), 1u);
}

struct TrogdorSilentStartTest : TrogdorFaultTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan plan;
    plan.silent_start = std::chrono::seconds(30);
    return plan;
  }
  TrogdorSilentStartTest() : TrogdorFaultTest(plan()) {}
};

TEST_F(TrogdorSilentStartTest, ASilentRobotRefusesTheSubscriptionWithTheReason) {
  devices.load("position:0 ( driver \"trogdor\" port \"$PORT\" )\n", robot.port());
  const auto started = std::chrono::steady_clock::now();
  EXPECT_FALSE(position().subscribe());
  EXPECT_LT(std::chrono::steady_clock::now() - started, 5s);
  EXPECT_FALSE(devices.log.first_with({"INIT", "is the robot on"}).empty()) << devices.log.all();
}

struct TrogdorSlowStartTest : TrogdorFaultTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan plan;
    plan.slow_start = std::chrono::milliseconds(700);
    return plan;
  }
  TrogdorSlowStartTest() : TrogdorFaultTest(plan()) {}
};

// Deaf for a while after every open (a USB adapter powering up): INIT is
// sent again until it answers.
TEST_F(TrogdorSlowStartTest, ARobotDeafAfterEachOpenIsAskedAgain) {
  start();
  EXPECT_TRUE(more_data(position(), 2));
  EXPECT_GE(counter(position().driver(), "retries"), 1u);
}

struct TrogdorNoisyLineTest : TrogdorFaultTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan plan;
    // Per byte, drop hits a 19-byte odometry reply 19 times as often.
    plan.garbage = 0.2;
    plan.bad_checksum = 0.05;
    plan.truncate = 0.03;
    plan.drop = 0.003;
    return plan;
  }
  TrogdorNoisyLineTest() : TrogdorFaultTest(plan()) {}
};

// Noise, corrupt and cut-short blocks, lost replies: counted, asked again,
// and the robot still drives and reports.
TEST_F(TrogdorNoisyLineTest, AFaultyLineLosesNoMotion) {
  start();
  write_command(position(), protocol::PositionCommand{.xspeed = 300});
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 300; }, 10s);
  ASSERT_TRUE(data) << devices.log.all();
  const auto stats = robot.runner().stats().faults;
  EXPECT_GT(stats.garbage_runs, 5u);
  EXPECT_GT(counter(position().driver(), "checksum_errors") + counter(position().driver(), "timeouts"), 0u);
  // Odometry is never integrated from a damaged block.
  const auto truth = robot.with([](TrogdorEmulator& e) { return e.drive().odometry(); });
  const auto now = latest<protocol::PositionData>(position());
  EXPECT_NEAR(now->xpos, truth.x * 1000, 40);
  EXPECT_EQ(counter(position().driver(), "skipped_readings"), 0u);
}

}  // namespace
}  // namespace playerkit::drivers::testing
