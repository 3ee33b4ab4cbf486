// er1_position against the emulated ER1 on a real pseudo-terminal, through
// the kit's driver harness: start-up as 1.5 did it, driving and odometry in
// both motor wirings, every request and option, a controller that never
// answers, unplugged and back, silent for a while, and each fault of a
// noisy line.

#include "families/er1/driver/er1_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/er1/driver/er1_options.hpp"
#include "families/er1/emulator/er1_emulator.hpp"
#include "families/er1/protocol/er1_commands.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace {

using emulators::Er1Emulator;
using Motor = Er1Emulator::Motor;
namespace rcm = hardware::er1;

emulators::Er1EmulatorOptions wired(int left_motor_port) {
  emulators::Er1EmulatorOptions options;
  options.left_motor_port = left_motor_port;
  return options;
}

emulators::FaultPlan fault(void (*set)(emulators::FaultPlan&)) {
  emulators::FaultPlan plan;
  set(plan);
  return plan;
}

struct Er1DriverTest : ::testing::Test {
  explicit Er1DriverTest(LineOptions options = {}, int left_motor_port = 0)
      : robot([left_motor_port] { return std::make_unique<Er1Emulator>(wired(left_motor_port)); }, std::move(options)) {}

  core::Device& position() { return devices.device(protocol::kPositionCode); }
  void start(const std::string& extra = "") {
    devices.load("position:0 ( driver \"er1_position\" port \"$PORT\" " + extra + ")\n", robot.port());
    ASSERT_TRUE(position().subscribe()) << devices.log.all();
  }
  void drive(int xspeed, int yawspeed) {
    write_command(position(), protocol::PositionCommand{.xpos = 0, .ypos = 0, .yaw = 0, .xspeed = xspeed, .yspeed = 0,
                                                        .yawspeed = yawspeed, .state = 1, .type = 0});
  }

  EmulatedLine<Er1Emulator> robot;
  ConfiguredDevices devices;
};

TEST_F(Er1DriverTest, StartsTheControllerAs15DidAndPublishesTheOrigin) {
  start();
  // INIT to both motors, then INIT again before each motor's reset.
  EXPECT_EQ(robot.with([](Er1Emulator& e) { return e.inits(); }), 4u);
  const auto data = next_data<protocol::PositionData>(position());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->xpos, 0);
  EXPECT_EQ(data->ypos, 0);
  EXPECT_EQ(data->yaw, 0);
  EXPECT_EQ(data->xspeed, 0);
  EXPECT_EQ(data->stall, 0);
  EXPECT_EQ(robot.with([](Er1Emulator& e) { return e.bad_checksums(); }), 0u);
}

TEST_F(Er1DriverTest, DrivesForwardAndReportsTheOdometryAndItsSpeed) {
  start();
  drive(200, 0);
  // 20 cm/s: trunc(20 x 16819.8); motor 0 is the mirrored one.
  ASSERT_TRUE(robot.wait_until([](Er1Emulator& e) { return e.running_velocity(Motor::port1) == 336396; }))
      << devices.log.all();
  EXPECT_EQ(robot.with([](Er1Emulator& e) { return e.running_velocity(Motor::port0); }), -336396);
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 150; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->xspeed, 200, 40);
  // Motor 0 starts one exchange before motor 1: on a loaded machine that
  // turns the robot a little, and the odometry must say so.
  const geometry::Pose2 truth = robot.with([](Er1Emulator& e) { return e.true_pose(); });
  EXPECT_NEAR(data->xpos, truth.x * 1000, 30);
  EXPECT_NEAR(data->ypos, truth.y * 1000, 5);
  const double yaw = data->yaw > 180 ? data->yaw - 360 : data->yaw;
  EXPECT_NEAR(yaw, truth.yaw * 180 / 3.14159265358979, 1.5);
  EXPECT_LT(std::abs(yaw), 3);
}

TEST_F(Er1DriverTest, TurnsTheWayTheClientSays) {
  start();
  drive(0, 45);
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.yaw >= 30 && d.yaw < 180; });
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_NEAR(data->yawspeed, 45, 10);
  EXPECT_GT(robot.with([](Er1Emulator& e) { return e.true_pose().yaw; }), 0.4);
  drive(0, -45);  // both wheels reverse: stopped first, then the other way
  EXPECT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.yawspeed < -30; }));
}

struct Er1MirroredWiringTest : Er1DriverTest {
  Er1MirroredWiringTest() : Er1DriverTest({}, 1) {}
};

TEST_F(Er1MirroredWiringTest, MotorDirMinusOneDrivesALeftMotorOnPort1) {
  start("motor_dir -1");
  drive(100, 30);
  ASSERT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.yaw >= 20 && d.yaw < 180; }))
      << devices.log.all();
  // The robot turned left, as the odometry says.
  EXPECT_GT(robot.with([](Er1Emulator& e) { return e.true_pose().yaw; }), 0.3);
  EXPECT_LT(robot.with([](Er1Emulator& e) { return e.running_velocity(Motor::port1); }), 0);
  EXPECT_GT(robot.with([](Er1Emulator& e) { return e.running_velocity(Motor::port0); }), 0);
}

TEST_F(Er1DriverTest, TooFastForAWheelKeepsTheArc) {
  start("axle 0.5");
  drive(700, 20);
  ASSERT_TRUE(robot.wait_until([](Er1Emulator& e) { return e.running_velocity(Motor::port1) != 0; }));
  const auto [left, right] = robot.with([](Er1Emulator& e) {
    return std::pair{-e.running_velocity(Motor::port0), e.running_velocity(Motor::port1)};
  });
  EXPECT_EQ(right, rcm::speed_register(500));
  const double rotation = 20 * 3.14159265358979 / 180 * 250;
  EXPECT_NEAR(double(left) / right, (700 - rotation) / (700 + rotation), 1e-4);
}

TEST_F(Er1DriverTest, AnswersGeometryMotorPowerAndOdometryRequests) {
  start();
  const auto geometry = ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.size, (std::array<std::uint16_t, 2>{450, 450}));

  drive(150, 0);
  ASSERT_TRUE(robot.wait_until([](Er1Emulator& e) { return e.moving(); }));
  EXPECT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq, .value = 0})));
  EXPECT_TRUE(robot.wait_until([](Er1Emulator& e) { return !e.moving(); }));
  EXPECT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq, .value = 1})));
  EXPECT_TRUE(robot.wait_until([](Er1Emulator& e) { return e.moving(); }));  // the last command again

  drive(0, 0);
  ASSERT_TRUE(robot.wait_until([](Er1Emulator& e) { return !e.moving(); }));
  // A reading whose counts were all taken after the stop: the pose is still.
  ASSERT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xspeed == 0; }));
  ASSERT_TRUE(more_data(position(), 1));
  EXPECT_TRUE(acked(ask(position(), protocol::PositionSetOdomRequest{
                                        .subtype = protocol::kPositionSetOdomReq, .x = 1000, .y = -2000, .theta = 90})));
  auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos == 1000; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->ypos, -2000);
  EXPECT_EQ(data->yaw, 90);
  EXPECT_TRUE(acked(ask(position(), protocol::PositionResetOdomConfig{.request = protocol::kPositionResetOdomReq})));
  data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos == 0 && d.ypos == 0; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->yaw, 0);

  EXPECT_TRUE(nacked(ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq, 0})));  // wrong size
  EXPECT_TRUE(nacked(ask(position(), std::vector<std::uint8_t>{99})));
}

TEST_F(Er1DriverTest, StopsTheMotorsWhenTheLastClientLeaves) {
  start();
  drive(200, 10);
  ASSERT_TRUE(robot.wait_until([](Er1Emulator& e) { return e.moving(); }));
  position().unsubscribe();
  EXPECT_TRUE(robot.wait_until([](Er1Emulator& e) { return !e.moving(); }));
  EXPECT_EQ(robot.with([](Er1Emulator& e) { return e.count(Motor::port0); }), 0);  // STOP_8 zeroes it
}

TEST_F(Er1DriverTest, DebugLogsTheOdometry) {
  start("debug 1");
  EXPECT_FALSE(devices.log.first_with({"odometry x 0.000 m"}).empty()) << devices.log.all();
}

TEST(Er1Options, BadValuesAreRefusedAtTheirPlace) {
  const std::string dir = config_error_of("position:0 ( driver \"er1_position\" port \"/tmp/er1\" motor_dir 0 )\n");
  EXPECT_NE(dir.find(":1:62: er1_position: motor_dir must be one of -1, 1"), std::string::npos) << dir;
  const std::string axle = config_error_of("position:0 ( driver \"er1_position\" axle 0 )\n");
  EXPECT_NE(axle.find(":1:41: er1_position: axle must be between"), std::string::npos) << axle;
  EXPECT_EQ(config_error_of("position:0 ( driver \"er1_position\" port \"/dev/usb/ttyUSB1\" axle 0.4 motor_dir -1 debug 1 )\n"),
            "no error");
}

// The README's options table is the schema's own (between "<!-- options
// er1_position -->" and "<!-- end options -->").
TEST(Er1Options, TheReadmeTableIsTheSchemas) {
  EXPECT_EQ(readme_options_table(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/er1/README.md",
                                 "er1_position"),
            er1::er1_option_schema().markdown());
}

TEST_F(Er1DriverTest, RefusesTheSubscriptionWhenThePortIsGone) {
  robot.replug(false);
  devices.load("position:0 ( driver \"er1_position\" port \"" + robot.port() + "\" )\n");
  EXPECT_FALSE(position().subscribe());
  EXPECT_FALSE(devices.log.first_with({"no such port"}).empty()) << devices.log.all();
}

struct Er1SilentControllerTest : Er1DriverTest {
  Er1SilentControllerTest()
      : Er1DriverTest({.tcp = false, .symlink = {}, .faults = fault([](emulators::FaultPlan& p) {
                         p.silent_start = std::chrono::hours(1);
                       })}) {}
};

// 1.5 blocked forever on the first read a controller left unanswered.
TEST_F(Er1SilentControllerTest, AControllerThatNeverAnswersRefusesTheSubscriptionInTime) {
  devices.load("position:0 ( driver \"er1_position\" port \"$PORT\" )\n", robot.port());
  const auto started = std::chrono::steady_clock::now();
  EXPECT_FALSE(position().subscribe());
  EXPECT_LT(std::chrono::steady_clock::now() - started, 3s);
  EXPECT_FALSE(devices.log.first_with({"no reply", "INIT"}).empty()) << devices.log.all();
}

struct Er1WakingTest : Er1DriverTest {
  Er1WakingTest()
      : Er1DriverTest({.tcp = false, .symlink = {}, .faults = fault([](emulators::FaultPlan& p) {
                         p.slow_start = std::chrono::milliseconds(400);
                       })}) {}
};

// A controller deaf and mute for 0.4 s each time the port opens (the kit's
// slow-start): the INIT asked again is answered, and the robot drives.
TEST_F(Er1WakingTest, AControllerSlowToWakeIsAskedAgainAndDrives) {
  start();
  drive(200, 0);
  EXPECT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 50; }))
      << devices.log.all();
}

struct Er1ReplugTest : Er1DriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("er1-replug");
    return {.tcp = false, .symlink = scratch.file("ttyER1"), .faults = {}};
  }
  Er1ReplugTest() : Er1DriverTest(on_a_symlink()) {}
};

TEST_F(Er1ReplugTest, ARobotUnpluggedAndBackIsFoundAgainWithItsPoseKept) {
  start();
  drive(200, 0);
  ASSERT_TRUE(data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 100; }));
  drive(0, 0);
  const auto before = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xspeed == 0; });
  ASSERT_TRUE(before);
  robot.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the ER1"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  ASSERT_TRUE(more_data(position(), 2)) << devices.log.all();
  const auto after = latest<protocol::PositionData>(position());
  EXPECT_NEAR(after->xpos, before->xpos, 10);  // the fresh controller's counts start from the old pose
}

struct Er1SilentSpellTest : Er1DriverTest {
  Er1SilentSpellTest()
      : Er1DriverTest({.tcp = false, .symlink = {}, .faults = fault([](emulators::FaultPlan& p) {
                         p.vanish_at = std::chrono::seconds(1);
                         p.vanish_for = std::chrono::seconds(2);
                       })}) {}
};

TEST_F(Er1SilentSpellTest, DataStopsWhileTheLineIsDeadAndResumes) {
  start();
  EXPECT_FALSE(devices.log.first_with({"lost the ER1", "no reply"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(position().available());
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(position(), 2)) << devices.log.all();
  EXPECT_EQ(counter(position().driver(), "reconnects"), 1u);
}

struct Er1SlowStartTest : Er1DriverTest {
  Er1SlowStartTest()
      : Er1DriverTest({.tcp = false, .symlink = {}, .faults = fault([](emulators::FaultPlan& p) {
                         p.silent_start = std::chrono::seconds(3);
                       })}) {}
};

TEST_F(Er1SlowStartTest, AControllerStillBootingRefusesTheFirstSubscriptionNotTheNext) {
  devices.load("position:0 ( driver \"er1_position\" port \"$PORT\" )\n", robot.port());
  EXPECT_FALSE(position().subscribe());
  EXPECT_TRUE(eventually([&] { return position().subscribe(); }, 10s)) << devices.log.all();
  EXPECT_TRUE(next_data<protocol::PositionData>(position()));
}

struct Er1NoisyLineTest : Er1DriverTest, ::testing::WithParamInterface<const char*> {
  Er1NoisyLineTest() : Er1DriverTest({.tcp = false, .symlink = {}, .faults = plan(GetParam())}) {}
  static emulators::FaultPlan plan(const std::string& kind) {
    emulators::FaultPlan plan;
    if (kind == "bad-checksum") plan.bad_checksum = 0.05;
    if (kind == "garbage") plan.garbage = 0.1;
    if (kind == "truncate") plan.truncate = 0.05;
    if (kind == "drop") plan.drop = 0.01;
    return plan;
  }
};

// Each reply the line spoils is asked for again; the robot drives and its
// odometry stays where the robot is.
TEST_P(Er1NoisyLineTest, SpoiltRepliesAreAskedForAgainAndTheOdometryHolds) {
  devices.load("position:0 ( driver \"er1_position\" port \"$PORT\" )\n", robot.port());
  // Three spoilt replies in a row (or a loaded machine) may refuse one subscription.
  ASSERT_TRUE(eventually([&] { return position().subscribe(); }, 10s)) << devices.log.all();
  drive(200, 0);
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 300; }, 10s);
  ASSERT_TRUE(data) << devices.log.all();
  const double true_x = robot.with([](Er1Emulator& e) { return e.true_pose().x; });
  EXPECT_NEAR(data->xpos, true_x * 1000, 40);
  const double true_y = robot.with([](Er1Emulator& e) { return e.true_pose().y; });
  EXPECT_NEAR(data->ypos, true_y * 1000, 20) << [&] {
    std::string figures;
    for (const auto& c : position().driver().counters()) figures += c.name + "=" + std::to_string(c.value) + " ";
    const auto [c0, c1] = robot.with([](Er1Emulator& e) { return std::pair{e.count(Motor::port0), e.count(Motor::port1)}; });
    const double left = -c0 * 0.00602836879, right = c1 * 0.00602836879;
    figures += " counts say heading " + std::to_string((right - left) / 380.0) + " rad, travel " +
               std::to_string((left + right) / 2) + " mm; data yaw " + std::to_string(data->yaw) + " ";
    return figures + devices.log.all();
  }();
  const auto& faults = robot.runner().stats().faults;
  EXPECT_GT(faults.bad_checksums + faults.garbage_runs + faults.truncated + faults.dropped_bytes, 0u);
  const core::Driver& driver = position().driver();
  EXPECT_GT(counter(driver, "retries") + counter(driver, "resyncs") + counter(driver, "checksum_errors"), 0u);
  EXPECT_EQ(devices.log.count("lost the ER1"), 0u) << devices.log.all();
}

INSTANTIATE_TEST_SUITE_P(EachFault, Er1NoisyLineTest, ::testing::Values("bad-checksum", "garbage", "truncate", "drop"));

}  // namespace
}  // namespace playerkit::drivers::testing
