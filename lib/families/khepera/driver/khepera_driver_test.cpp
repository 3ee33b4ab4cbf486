// khepera_position and khepera_ir against the emulated Khepera on a real
// pseudo-terminal, through the kit's driver harness: the start-up and
// subscription traffic of khepera.md §2, velocities in the interface's
// units, odometry in the world frame, every request and option, the shared
// link, and each fault of the kit.

#include "families/khepera/driver/khepera_drivers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <memory>
#include <numbers>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/khepera/driver/khepera_options.hpp"
#include "families/khepera/emulator/khepera_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/position.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace {

using emulators::KheperaEmulator;
using hardware::khepera::WheelSpeeds;

struct KheperaDriverTest : ::testing::Test {
  explicit KheperaDriverTest(LineOptions options = {})
      : robot([] { return std::make_unique<KheperaEmulator>(); }, std::move(options)) {}

  core::Device& position() { return devices.device(protocol::kPositionCode); }
  core::Device& ir() { return devices.device(protocol::kIrCode); }
  void load(const std::string& position_extra = "", const std::string& ir_extra = "") {
    devices.load("position:0 ( driver \"khepera_position\" port \"$PORT\" " + position_extra +
                     ")\nir:0 ( driver \"khepera_ir\" " + ir_extra + ")\n",
                 robot.port());
  }
  void start(const std::string& position_extra = "") {
    load(position_extra);
    ASSERT_TRUE(position().subscribe()) << devices.log.all();
  }
  void motors_on() { ASSERT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{.request = 2, .value = 1}))); }
  WheelSpeeds speeds() { return robot.with([](KheperaEmulator& e) { return e.speeds(); }); }

  EmulatedLine<KheperaEmulator> robot;
  ConfiguredDevices devices;
};

TEST_F(KheperaDriverTest, StartsLikePlayerAndPublishesOdometryAndIr) {
  start();
  // The first position subscription: D,0,0 and G,0,0 (khepera.md §2).
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.set_speed_commands() >= 1; }));
  const auto data = next_data<protocol::PositionData>(position());
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_EQ(data->xpos, 0);
  EXPECT_EQ(data->yaw, 0);
  ASSERT_TRUE(ir().subscribe()) << devices.log.all();
  const auto readings = next_data<protocol::IrData>(ir());
  ASSERT_TRUE(readings);
  EXPECT_EQ(readings->range_count, 8);
  EXPECT_EQ(readings->voltages[0], 1);    // nothing near
  EXPECT_EQ(readings->ranges[0], 642);    // 10 x 64.158 mm, the farthest the calibration knows
  EXPECT_EQ(counter(position().driver(), "robot_lost"), 0u);
}

TEST_F(KheperaDriverTest, VelocitiesAreHonouredInTheInterfacesUnits) {
  start();
  // Motors off after the first subscription, as in 1.5: the wheels stay still.
  write_command(position(), protocol::PositionCommand{.xspeed = 100});
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.set_speed_commands() >= 3; }));
  EXPECT_EQ(speeds(), (WheelSpeeds{0, 0}));
  motors_on();
  write_command(position(), protocol::PositionCommand{.xspeed = 100});
  // 100 mm/s is 12 pulses per 10 ms (1.5 sent 8: 0.67x).
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds() == WheelSpeeds{12, 12}; }))
      << devices.log.all();
  const auto moving = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xspeed == 100; });
  ASSERT_TRUE(moving);
  EXPECT_EQ(moving->yawspeed, 0);
  // A turn to the left, counter-clockwise positive as the interface says.
  write_command(position(), protocol::PositionCommand{.xspeed = 0, .yawspeed = 90});
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds() == WheelSpeeds{-5, 5}; }));
  const auto turning = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.yawspeed > 0; });
  ASSERT_TRUE(turning);
  EXPECT_NEAR(turning->yawspeed, 84, 1);  // 5 pulses: 0.4167 mm / 10 ms on each wheel over 57 mm
  ASSERT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{.request = 2, .value = 0})));
  EXPECT_EQ(speeds(), (WheelSpeeds{0, 0}));
}

TEST_F(KheperaDriverTest, EncoderResolutionSetsThePulsesAndTheOdometry) {
  start("encoder_res 0.1");
  motors_on();
  // 100 mm/s at 0.1 mm a pulse: 10 pulses per 10 ms.
  write_command(position(), protocol::PositionCommand{.xspeed = 100});
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds() == WheelSpeeds{10, 10}; }));
  // The emulated robot counts 12 pulses a millimetre: the odometry reads
  // what the configured resolution says, 1.2 x the truth.
  ASSERT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 60; }));
  write_command(position(), protocol::PositionCommand{});
  ASSERT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds() == WheelSpeeds{}; }));
  const auto truth = robot.with([](KheperaEmulator& e) { return e.true_pose(); });
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xspeed == 0; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->xpos, truth.x * 1000.0 * 1.2, 2.0);
}

TEST_F(KheperaDriverTest, OdometryFollowsTheRobotInTheWorldFrame) {
  start();
  motors_on();
  write_command(position(), protocol::PositionCommand{.xspeed = 50, .yawspeed = 30});
  ASSERT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.yaw >= 60 && d.yaw < 180; },
                                                5s));
  write_command(position(), protocol::PositionCommand{});
  ASSERT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds() == WheelSpeeds{}; }));
  const auto truth = robot.with([](KheperaEmulator& e) { return e.true_pose(); });
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xspeed == 0; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->xpos, truth.x * 1000.0, 2.0);
  EXPECT_NEAR(data->ypos, truth.y * 1000.0, 2.0);
  EXPECT_GT(data->ypos, 10);  // the increments are rotated (1.5 added them unrotated)
  EXPECT_NEAR(data->yaw, truth.yaw * 180.0 / std::numbers::pi, 1.5);
}

TEST_F(KheperaDriverTest, AnswersEveryPositionRequest) {
  start();
  const auto geometry = ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.pose, (std::array<std::int16_t, 3>{0, 0, 0}));
  EXPECT_EQ(geom.size, (std::array<std::uint16_t, 2>{570, 570}));  // x scale_factor 10, as 1.5
  EXPECT_TRUE(acked(ask(position(), protocol::PositionVelocityModeConfig{.request = 3, .value = 1})));
  motors_on();
  write_command(position(), protocol::PositionCommand{.xspeed = 80});
  ASSERT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 30; }));
  write_command(position(), protocol::PositionCommand{});
  EXPECT_TRUE(acked(ask(position(), protocol::PositionResetOdomConfig{.request = 4})));
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return std::abs(e.left_counter()) < 50; }));
  EXPECT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos == 0; }));
  // SET_ODOM's values are honoured (1.5 zeroed the pose whatever they were).
  EXPECT_TRUE(acked(ask(position(), protocol::PositionSetOdomRequest{.subtype = 9, .x = 120, .y = -40, .theta = 90})));
  const auto moved = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos == 120; });
  ASSERT_TRUE(moved);
  EXPECT_EQ(moved->ypos, -40);
  EXPECT_EQ(moved->yaw, 90);
  EXPECT_TRUE(nacked(ask(position(), protocol::PositionPositionModeRequest{.subtype = 5, .state = 1})));
  EXPECT_TRUE(nacked(ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq, 0})));
  EXPECT_TRUE(nacked(ask(position(), std::vector<std::uint8_t>{42})));
}

TEST_F(KheperaDriverTest, GeometryAndScaleComeFromTheConfiguration) {
  load("pose [5 0 0] size [60 50] scale_factor 2", "pose_count 3 poses [10 0 0 0 10 90 0 -10 -90]");
  ASSERT_TRUE(position().subscribe()) << devices.log.all();
  const auto geometry = ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.pose[0], 10);
  EXPECT_EQ(geom.size, (std::array<std::uint16_t, 2>{120, 100}));
  ASSERT_TRUE(ir().subscribe());
  const auto poses = ask(ir(), std::vector<std::uint8_t>{protocol::kIrPoseReq});
  ASSERT_TRUE(acked(poses));
  const auto reply = protocol::decode<protocol::IrPoseRequest>(poses->payload);
  EXPECT_EQ(reply.poses.pose_count, 3);
  EXPECT_EQ(reply.poses.poses[1], (std::array<std::int16_t, 3>{0, 20, 90}));
  EXPECT_EQ(reply.poses.poses[2], (std::array<std::int16_t, 3>{0, -20, -90}));
  EXPECT_TRUE(nacked(ask(ir(), std::vector<std::uint8_t>{protocol::kIrPoseReq, 0})));
  EXPECT_TRUE(nacked(ask(ir(), std::vector<std::uint8_t>{9})));
}

TEST_F(KheperaDriverTest, TheDefaultIrPosesAreTheSheets) {
  load();
  ASSERT_TRUE(ir().subscribe()) << devices.log.all();
  const auto poses = ask(ir(), std::vector<std::uint8_t>{protocol::kIrPoseReq});
  ASSERT_TRUE(acked(poses));
  const auto reply = protocol::decode<protocol::IrPoseRequest>(poses->payload);
  EXPECT_EQ(reply.poses.pose_count, 8);
  EXPECT_EQ(reply.poses.poses[0], (std::array<std::int16_t, 3>{100, 240, 90}));
  EXPECT_EQ(reply.poses.poses[4], (std::array<std::int16_t, 3>{190, -170, -45}));
  EXPECT_EQ(reply.poses.poses[7], (std::array<std::int16_t, 3>{-240, 100, 180}));
}

// The shared link: opened by the first device, one connection for both,
// the wheels stopped when the position device leaves and the line closed
// after the last.
TEST_F(KheperaDriverTest, TheLastDeviceStopsTheRobotAndClosesTheLine) {
  start();
  ASSERT_TRUE(ir().subscribe());
  motors_on();
  write_command(position(), protocol::PositionCommand{.xspeed = 60});
  ASSERT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds().left > 0; }));
  position().unsubscribe();
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds() == WheelSpeeds{}; }));
  EXPECT_TRUE(more_data(ir(), 2));
  EXPECT_EQ(devices.log.count("closed"), 0u);
  ir().unsubscribe();
  EXPECT_FALSE(devices.log.first_with({"closed (the last device left)"}).empty()) << devices.log.all();
}

TEST_F(KheperaDriverTest, ARobotStillDrivingIsStoppedWhenTheLastDeviceLeaves) {
  start();
  motors_on();
  write_command(position(), protocol::PositionCommand{.xspeed = 60});
  ASSERT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds().left > 0; }));
  position().unsubscribe();
  EXPECT_TRUE(robot.wait_until([](KheperaEmulator& e) { return e.speeds() == WheelSpeeds{}; }));
}

TEST(KheperaOptions, BadValuesAreRefusedAtTheirPlace) {
  const auto tiny = config_error_of("position:0 ( driver \"khepera_position\" encoder_res 0 )\n");
  EXPECT_NE(tiny.find(":1:52: khepera_position: encoder_res must be between"), std::string::npos) << tiny;
  const auto short_poses =
      config_error_of("ir:0 ( driver \"khepera_ir\" port \"/tmp/k\" pose_count 2 poses [1 2 3] )\n");
  EXPECT_NE(short_poses.find("khepera_ir: poses needs x, y and heading"), std::string::npos) << short_poses;
  const auto differ = config_error_of(
      "position:0 ( driver \"khepera_position\" port \"/tmp/a\" )\nir:0 ( driver \"khepera_ir\" port \"/tmp/b\" )\n");
  EXPECT_NE(differ.find(":2:"), std::string::npos) << differ;
  // 1.5's names: scale (the manual's) and scale_factor (the source's).
  EXPECT_EQ(config_error_of("position:0 ( driver \"khepera_position\" scale 5 )\n"), "no error");
}

// The README's option tables are the schemas' own.
TEST(KheperaOptions, TheReadmeTablesAreGeneratedFromTheSchemas) {
  std::ifstream in(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/khepera/README.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const auto table = [&all](const std::string& name) {
    const std::string begin = "<!-- " + name + " options -->\n";
    const auto start = all.find(begin);
    const auto end = all.find("<!-- end " + name + " options -->", start);
    if (start == std::string::npos || end == std::string::npos) return std::string("no table");
    return all.substr(start + begin.size(), end - start - begin.size());
  };
  EXPECT_EQ(table("position"), khepera::khepera_position_schema().markdown());
  EXPECT_EQ(table("ir"), khepera::khepera_ir_schema().markdown());
}

// More sensors than the default eight, each with its pose and calibration.
TEST_F(KheperaDriverTest, MoreSensorsThanTheDefaultTakeTheirPosesFromTheConfiguration) {
  load("", "pose_count 9 poses [1 0 0 2 0 0 3 0 0 4 0 0 5 0 0 6 0 0 7 0 0 8 0 0 9 0 45] ir_calib_a [1 1 1 1 1 1 1 1 100]");
  ASSERT_TRUE(ir().subscribe()) << devices.log.all();
  const auto poses = ask(ir(), std::vector<std::uint8_t>{protocol::kIrPoseReq});
  ASSERT_TRUE(acked(poses));
  const auto reply = protocol::decode<protocol::IrPoseRequest>(poses->payload);
  EXPECT_EQ(reply.poses.pose_count, 9);
  EXPECT_EQ(reply.poses.poses[8], (std::array<std::int16_t, 3>{90, 0, 45}));
  // The emulated robot has eight: their readings, and the robot not lost.
  const auto data = next_data<protocol::IrData>(ir());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->range_count, 8);
  EXPECT_EQ(data->ranges[0], 10);  // 10 x 1 x 1^b
  EXPECT_TRUE(more_data(ir(), 3));
  EXPECT_EQ(counter(ir().driver(), "robot_lost"), 0u) << devices.log.all();
}

TEST_F(KheperaDriverTest, RefusesTheSubscriptionWhenNothingAnswers) {
  robot.replug(false);
  devices.load("position:0 ( driver \"khepera_position\" port \"" + robot.port() +
               "\" connect_timeout 0.5 )\n");
  const auto started = std::chrono::steady_clock::now();
  EXPECT_FALSE(position().subscribe());
  EXPECT_LT(std::chrono::steady_clock::now() - started, 3s);
}

struct KheperaSilentStartTest : KheperaDriverTest {
  KheperaSilentStartTest() : KheperaDriverTest({.tcp = false, .symlink = {}, .faults = silent()}) {}
  static emulators::FaultPlan silent() {
    emulators::FaultPlan plan;
    plan.silent_start = std::chrono::seconds(30);
    return plan;
  }
};

// A robot that says nothing: a clear error within connect_timeout.
TEST_F(KheperaSilentStartTest, ASilentRobotIsAClearErrorWithinTheTimeout) {
  load("connect_timeout 0.5");
  const auto started = std::chrono::steady_clock::now();
  EXPECT_FALSE(position().subscribe());
  EXPECT_LT(std::chrono::steady_clock::now() - started, 3s);
  EXPECT_FALSE(devices.log.first_with({"no Khepera answered E"}).empty()) << devices.log.all();
}

struct KheperaSlowStartTest : KheperaDriverTest {
  KheperaSlowStartTest() : KheperaDriverTest({.tcp = false, .symlink = {}, .faults = slow()}) {}
  static emulators::FaultPlan slow() {
    emulators::FaultPlan plan;
    plan.slow_start = std::chrono::milliseconds(800);
    return plan;
  }
};

// A robot deaf for a while after the port opens: E is asked again until it
// answers, within connect_timeout.
TEST_F(KheperaSlowStartTest, ARobotSlowToWakeIsWaitedFor) {
  const auto opened = std::chrono::steady_clock::now();
  start();
  EXPECT_GT(std::chrono::steady_clock::now() - opened, 600ms);
  EXPECT_TRUE(next_data<protocol::PositionData>(position())) << devices.log.all();
}

struct KheperaVanishTest : KheperaDriverTest {
  KheperaVanishTest() : KheperaDriverTest({.tcp = false, .symlink = {}, .faults = spell()}) {}
  static emulators::FaultPlan spell() {
    emulators::FaultPlan plan;
    plan.vanish_at = std::chrono::seconds(1);
    plan.vanish_for = std::chrono::seconds(2);
    return plan;
  }
};

// The line goes dead both ways for a while: data stops, the devices are
// unavailable, and both come back when the robot answers again.
TEST_F(KheperaVanishTest, DataStopsAndResumesWhenTheRobotVanishesAndReturns) {
  start();
  ASSERT_TRUE(ir().subscribe());
  EXPECT_FALSE(devices.log.first_with({"lost the robot"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(position().available());
  EXPECT_FALSE(devices.log.first_with({"the robot is back"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(position(), 2)) << devices.log.all();
  EXPECT_TRUE(more_data(ir(), 2));
  EXPECT_EQ(counter(position().driver(), "reconnects"), 1u);
}

struct KheperaReplugTest : KheperaDriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("khepera-replug");
    return {.tcp = false, .symlink = scratch.file("ttyKhepera"), .faults = {}};
  }
  KheperaReplugTest() : KheperaDriverTest(on_a_symlink()) {}
};

TEST_F(KheperaReplugTest, ARobotUnpluggedAndBackIsFoundAgain) {
  start();
  ASSERT_TRUE(next_data<protocol::PositionData>(position()));
  robot.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the robot"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"the robot is back"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(position(), 2)) << devices.log.all();
}

struct KheperaNoisyLineTest : KheperaDriverTest {
  static emulators::FaultPlan noisy() {
    emulators::FaultPlan plan;
    plan.garbage = 0.2;
    plan.truncate = 0.03;
    plan.drop = 0.001;
    plan.bad_checksum = 1.0;  // replies carry none: nothing to corrupt
    return plan;
  }
  KheperaNoisyLineTest() : KheperaDriverTest({.tcp = false, .symlink = {}, .faults = noisy()}) {}
};

// Garbage, cut replies and lost bytes: a reply is found behind the noise on
// its line, one cut short or lost is asked again, and the robot is never
// counted lost.
TEST_F(KheperaNoisyLineTest, NoiseCutAndLostRepliesAreAskedAgain) {
  start();
  motors_on();
  write_command(position(), protocol::PositionCommand{.xspeed = 50});
  EXPECT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 40; }, 10s))
      << devices.log.all();
  // Until many replies went through the faults, the data still flowing.
  EXPECT_TRUE(eventually(
      [&] {
        const auto faults = robot.runner().stats().faults;
        return faults.garbage_runs + faults.truncated > 20;
      },
      30s));
  EXPECT_TRUE(more_data(position(), 3)) << devices.log.all();
  EXPECT_EQ(counter(position().driver(), "robot_lost"), 0u) << devices.log.all();
}

}  // namespace
}  // namespace playerkit::drivers::testing
