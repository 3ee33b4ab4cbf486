// The segwayrmp drivers against the emulated RMP behind an slcan adapter on
// a real pseudo-terminal: the adapter opened as Lawicel says, the three
// devices of one robot on one bus, motors enabled by request, the speed,
// acceleration and command-timeout limits, every request, 1.5's names and
// configuration, bad options at their place, and the kit's faults.
#include "families/segwayrmp/driver/segwayrmp_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <thread>

#include "drivers/driver_harness_test_support.hpp"
#include "families/segwayrmp/driver/rmp_options.hpp"
#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"
#include "links/can/can_bus.hpp"
#include "links/can/slcan.hpp"
#include "links/can/socketcan_link.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/position3d.hpp"
#include "protocol/messages/power.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace segwayrmp_driver_test {

using emulators::SegwayRmpEmulator;
namespace rmp = hardware::segwayrmp;

struct SegwayRmpDriverTest : ::testing::Test {
  explicit SegwayRmpDriverTest(LineOptions options = {})
      : robot([] { return std::make_unique<SegwayRmpEmulator>(); }, std::move(options)) {}

  core::Device& position() { return devices.device(protocol::kPositionCode); }
  core::Device& position3d() { return devices.device(protocol::kPosition3dCode); }
  core::Device& power() { return devices.device(protocol::kPowerCode); }
  // The robot as 1.5's configuration form names it, on the emulator's pty.
  void start(const std::string& extra = "") {
    devices.load("position:0 ( driver \"rmpposition\" canio \"slcan\" port \"$PORT\" " + extra +
                     ")\nposition3d:0 ( driver \"rmpposition\" )\npower:0 ( driver \"rmppower\" )\n",
                 robot.port());
    ASSERT_TRUE(position().subscribe()) << devices.log.all();
  }
  void enable_motors() {
    ASSERT_TRUE(acked(ask(position(), protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq,
                                                                      .value = 1})));
  }
  // Commands at a client's pace until `until` holds of the emulator.
  template <class Condition>
  bool drive(const protocol::PositionCommand& command, Condition until, std::chrono::milliseconds limit = 5s) {
    return eventually(
        [&] {
          write_command(position(), command);
          return robot.with([&](SegwayRmpEmulator& e) { return static_cast<bool>(until(e)); });
        },
        limit);
  }

  EmulatedLine<SegwayRmpEmulator> robot;
  ConfiguredDevices devices;
};

TEST_F(SegwayRmpDriverTest, OpensTheAdapterAndPublishesTheRobotOnEveryDevice) {
  start();
  EXPECT_TRUE(robot.with([](SegwayRmpEmulator& e) { return e.channel_open() && e.bitrate() == 500000; }));
  ASSERT_TRUE(position3d().subscribe()) << devices.log.all();
  ASSERT_TRUE(power().subscribe()) << devices.log.all();
  const auto data = next_data<protocol::PositionData>(position());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->xpos, 0);
  EXPECT_EQ(data->xspeed, 0);
  ASSERT_TRUE(next_data<protocol::Position3dData>(position3d()));
  const auto battery = next_data<protocol::PowerData>(power());
  ASSERT_TRUE(battery);
  EXPECT_EQ(battery->charge, 720);  // 100 % of 72 V
  EXPECT_EQ(devices.log.count("the Segway RMP answers"), 1u) << devices.log.all();  // one bus for all three
}

TEST_F(SegwayRmpDriverTest, CommandsAreIgnoredUntilTheMotorsAreEnabled) {
  start();
  EXPECT_FALSE(drive({.xspeed = 300}, [](SegwayRmpEmulator& e) { return e.commanded_speed() > 0; }, 600ms));
  enable_motors();
  EXPECT_TRUE(drive({.xspeed = 300}, [](SegwayRmpEmulator& e) { return e.commanded_speed() > 0.29; }));
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos > 100; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->xspeed, 300, 3);
  EXPECT_EQ(data->ypos, 0);
}

TEST_F(SegwayRmpDriverTest, SpeedsAreHeldWithinMaxXspeedAndMaxYawspeed) {
  start("max_xspeed -400 max_yawspeed 20");  // 1.5 took the absolute value
  enable_motors();
  ASSERT_TRUE(drive({.xspeed = 2000, .yawspeed = 90},
                    [](SegwayRmpEmulator& e) { return e.commanded_speed() > 0.3; }));
  EXPECT_NEAR(robot.with([](SegwayRmpEmulator& e) { return e.commanded_speed(); }), 0.4, 0.005);
  EXPECT_NEAR(robot.with([](SegwayRmpEmulator& e) { return e.commanded_turn_rate(); }), 20 * M_PI / 180, 0.003);
  const auto turning = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.yawspeed > 0; });
  ASSERT_TRUE(turning);
  EXPECT_EQ(turning->yawspeed, 20);  // counter-clockwise positive again
}

TEST_F(SegwayRmpDriverTest, AnAccelerationLimitRampsTheCommandedSpeed) {
  start("max_xspeed 1000 max_xaccel 500");
  enable_motors();
  const auto began = std::chrono::steady_clock::now();
  ASSERT_TRUE(drive({.xspeed = 1000}, [](SegwayRmpEmulator& e) { return e.commanded_speed() > 0.99; }));
  // 1 m/s at 0.5 m/s² takes two seconds.
  EXPECT_GT(std::chrono::steady_clock::now() - began, 1800ms);
}

TEST_F(SegwayRmpDriverTest, AClientThatStopsSendingStopsTheRobot) {
  start("command_timeout 0.3");
  enable_motors();
  ASSERT_TRUE(drive({.xspeed = 500}, [](SegwayRmpEmulator& e) { return e.commanded_speed() > 0.4; }));
  const auto silent_from = std::chrono::steady_clock::now();
  ASSERT_TRUE(robot.wait_until([](SegwayRmpEmulator& e) { return e.commanded_speed() == 0; }, 3s));
  EXPECT_GT(std::chrono::steady_clock::now() - silent_from, 250ms);
  EXPECT_EQ(robot.with([](SegwayRmpEmulator& e) { return e.watchdog_stops(); }), 0u);  // the driver's doing
  EXPECT_TRUE(eventually([&] { return counter(position().driver(), "command_timeouts") == 1; }));
}

TEST_F(SegwayRmpDriverTest, Position3dCommandsTurnInArcSecondsASecond) {
  start();
  ASSERT_TRUE(position3d().subscribe());
  ASSERT_TRUE(acked(ask(position3d(), protocol::Position3dPowerConfig{.request = 2, .value = 1})));
  EXPECT_TRUE(eventually(
      [&] {
        write_command(position3d(), protocol::Position3dCommand{.xspeed = 200, .yawspeed = 10 * 3600});
        return robot.with([](SegwayRmpEmulator& e) { return e.commanded_turn_rate() > 0.17; });
      },
      5s));
  const auto data = data_when<protocol::Position3dData>(position3d(), [](const auto& d) { return d.yawspeed > 0; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->yawspeed, 10 * 3600, 3600);
  EXPECT_TRUE(nacked(ask(position3d(), std::vector<std::uint8_t>{1})));  // position3d's GET_GEOM
}

TEST_F(SegwayRmpDriverTest, GeometryAndOdometryReset) {
  start();
  const auto geometry = ask(position(), std::vector<std::uint8_t>{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(geometry));
  const auto geom = protocol::decode<protocol::PositionGeom>(geometry->payload);
  EXPECT_EQ(geom.size, (std::array<std::uint16_t, 2>{508, 610}));
  enable_motors();
  ASSERT_TRUE(drive({.xspeed = 500}, [](SegwayRmpEmulator& e) { return e.status().fore_aft_displacement > 10000; }));
  ASSERT_TRUE(acked(ask(position(), protocol::PositionResetOdomConfig{.request = protocol::kPositionResetOdomReq})));
  EXPECT_TRUE(robot.wait_until([](SegwayRmpEmulator& e) { return e.status().fore_aft_displacement < 5000; }));
  write_command(position(), protocol::PositionCommand{});
  const auto data = data_when<protocol::PositionData>(position(), [](const auto& d) { return d.xpos < 200; });
  ASSERT_TRUE(data);
  EXPECT_LT(data->xpos, 200);
}

TEST_F(SegwayRmpDriverTest, RmpSettingsBecomeStatusCommands) {
  start();
  const auto setting = [&](std::uint8_t subtype, std::uint16_t value) {
    return acked(ask(position(), protocol::RmpConfig{.subtype = subtype, .value = value}));
  };
  EXPECT_TRUE(setting(protocol::kPositionRmpVelocityScale, 8));
  EXPECT_TRUE(setting(protocol::kPositionRmpAccelScale, 0x0104));  // only the low byte travels
  EXPECT_TRUE(setting(protocol::kPositionRmpTurnScale, 12));
  EXPECT_TRUE(setting(protocol::kPositionRmpGainSchedule, 2));
  EXPECT_TRUE(setting(protocol::kPositionRmpCurrentLimit, 5));
  EXPECT_TRUE(robot.wait_until([](SegwayRmpEmulator& e) {
    return e.scale(rmp::StatusCommand::velocity_scale) == 8 && e.scale(rmp::StatusCommand::acceleration_scale) == 4 &&
           e.scale(rmp::StatusCommand::turn_scale) == 12 && e.scale(rmp::StatusCommand::gain_schedule) == 2 &&
           e.scale(rmp::StatusCommand::current_limit) == 5;
  }));
  EXPECT_TRUE(setting(protocol::kPositionRmpRstIntegrators, rmp::kResetYaw));
  EXPECT_TRUE(setting(protocol::kPositionRmpShutdown, 0));
  EXPECT_TRUE(robot.wait_until([](SegwayRmpEmulator& e) { return e.shut_down(); }));
  EXPECT_FALSE(devices.log.first_with({"lost the robot", "no status"}).empty()) << devices.log.all();
}

TEST_F(SegwayRmpDriverTest, TheLastDeviceToLeaveStopsTheRobotAndClosesTheChannel) {
  start();
  ASSERT_TRUE(power().subscribe());
  enable_motors();
  ASSERT_TRUE(drive({.xspeed = 500}, [](SegwayRmpEmulator& e) { return e.commanded_speed() > 0.4; }));
  power().unsubscribe();
  EXPECT_TRUE(robot.with([](SegwayRmpEmulator& e) { return e.channel_open(); }));
  position().unsubscribe();
  EXPECT_TRUE(robot.wait_until([](SegwayRmpEmulator& e) { return !e.channel_open() && e.commanded_speed() == 0; }));
  EXPECT_EQ(robot.with([](SegwayRmpEmulator& e) { return e.watchdog_stops(); }), 0u);
}

TEST_F(SegwayRmpDriverTest, TheManualsNameServesAllThreeInterfaces) {
  devices.load("position:0 ( driver \"segwayrmp\" port \"$PORT\" bitrate 500000 )\n"  // a port: slcan
               "power:0 ( driver \"segwayrmp\" )\n",
               robot.port());
  ASSERT_TRUE(position().subscribe()) << devices.log.all();
  ASSERT_TRUE(power().subscribe()) << devices.log.all();
  EXPECT_TRUE(next_data<protocol::PowerData>(power()));
}

TEST_F(SegwayRmpDriverTest, ASilentRobotRefusesTheSubscriptionWithTheReason) {
  robot.replug(false);
  devices.load("position:0 ( driver \"segwayrmp\" canio \"slcan\" port \"" + robot.port() + "\" )\n");
  EXPECT_FALSE(position().subscribe());
}

TEST(SegwayRmpOptions, KvaserIsRefusedAtItsPlaceWithTheWayOut) {
  const std::string error = config_error_of("position:0 ( driver \"rmpposition\" canio \"kvaser\" )\n");
  EXPECT_NE(error.find("test.cfg:1:41: rmpposition: canio kvaser"), std::string::npos) << error;
  EXPECT_NE(error.find("canio \"socketcan\" and device \"can0\""), std::string::npos) << error;
  EXPECT_NE(error.find("slcan"), std::string::npos) << error;
  const std::string rate = config_error_of("position:0 ( driver \"segwayrmp\" canio \"slcan\" bitrate 400000 )\n");
  EXPECT_NE(rate.find("bitrate"), std::string::npos) << rate;
  const std::string differ = config_error_of(
      "position:0 ( driver \"rmpposition\" canio \"slcan\" )\npower:0 ( driver \"rmppower\" canio \"socketcan\" )\n");
  EXPECT_NE(differ.find("canio"), std::string::npos) << differ;
}

TEST(SegwayRmpOptions, TheReadmeTableIsTheSchemas) {
  const std::string table = segwayrmp::rmp_option_schema().markdown();
  EXPECT_EQ(readme_options_table(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/segwayrmp/README.md",
                                 "segwayrmp"),
            table);
}

TEST(SegwayRmpOptions, SocketCanWithoutTheInterfaceRefusesTheSubscriptionNamingIt) {
  ConfiguredDevices devices;
  devices.load("position:0 ( driver \"segwayrmp\" canio \"socketcan\" device \"nosuchcan3\" )\n");
  EXPECT_FALSE(devices.device(protocol::kPositionCode).subscribe());
  EXPECT_FALSE(devices.log.first_with({"nosuchcan3"}, 1s).empty()) << devices.log.all();
}

// The emulated robot on vcan0: a thread of the test carries its slcan lines
// to the bus as frames and the bus's frames to it (the emulator itself
// speaks slcan only).
class RobotOnVcan {
 public:
  RobotOnVcan() : link_("vcan0", {}), bus_(link_, links::can::CanTransport::socketcan) {
    thread_ = std::jthread([this](std::stop_token stop) { run(stop); });
  }
  template <class Read>
  auto with(Read read) {
    std::lock_guard lock(mutex_);
    return read(robot_);
  }

 private:
  void say(const std::string& text, emulators::Duration now) {
    robot_.receive(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()), now, 0);
  }
  void run(const std::stop_token& stop) {
    const auto began = std::chrono::steady_clock::now();
    const auto since = [&] { return std::chrono::steady_clock::now() - began; };
    {
      std::lock_guard lock(mutex_);
      say("O\r", since());
    }
    while (!stop.stop_requested()) {
      std::vector<emulators::Telegram> out;
      {
        std::lock_guard lock(mutex_);
        robot_.advance(since());
        out = robot_.take_output();
      }
      for (const emulators::Telegram& telegram : out) {
        const std::string line(telegram.bytes.begin(), telegram.bytes.end());
        if (const auto frame = links::can::parse_slcan_frame(line.substr(0, line.size() - 1))) {
          bus_.send(*frame, links::deadline_in(100ms));
        }
      }
      if (const auto frame = bus_.receive(links::deadline_in(2ms))) {
        std::lock_guard lock(mutex_);
        say(links::can::slcan_frame_line(*frame), since());
      }
    }
  }

  links::can::SocketCanLink link_;
  links::can::CanBus bus_;
  std::mutex mutex_;
  SegwayRmpEmulator robot_;
  std::jthread thread_;
};

TEST(SegwayRmpSocketCan, TheRobotOnVcan0IsDrivenThroughSocketCan) {
  const std::string reason = links::can::socketcan_unavailable_reason("vcan0");
  if (!reason.empty()) GTEST_SKIP() << "no vcan0 here (" << reason << "); the slcan tests cover the driver";
  RobotOnVcan robot;
  ConfiguredDevices devices;
  devices.load("position:0 ( driver \"segwayrmp\" canio \"socketcan\" device \"vcan0\" )\n");
  core::Device& position = devices.device(protocol::kPositionCode);
  ASSERT_TRUE(position.subscribe()) << devices.log.all();
  ASSERT_TRUE(acked(ask(position, protocol::PositionPowerConfig{.request = protocol::kPositionMotorPowerReq,
                                                                  .value = 1})));
  EXPECT_TRUE(eventually(
      [&] {
        write_command(position, protocol::PositionCommand{.xspeed = 300});
        return robot.with([](SegwayRmpEmulator& e) { return e.commanded_speed() > 0.29; });
      },
      5s));
  EXPECT_TRUE(data_when<protocol::PositionData>(position, [](const auto& d) { return d.xpos > 50; }));
}

struct SegwayRmpVanishTest : SegwayRmpDriverTest {
  SegwayRmpVanishTest() : SegwayRmpDriverTest({.tcp = false, .symlink = {}, .faults = spell()}) {}
  static emulators::FaultPlan spell() {
    emulators::FaultPlan plan;
    plan.vanish_at = std::chrono::seconds(2);
    // Long enough that a slow (sanitized, loaded) run still sees the loss
    // and the robot's watchdog before the line comes back.
    plan.vanish_for = std::chrono::seconds(5);
    return plan;
  }
};

// The line goes dead both ways: the driver loses the robot, whose own
// watchdog stops it; data resumes when the line is back.
TEST_F(SegwayRmpVanishTest, ALinkThatGoesDeadStopsTheRobotAndComesBack) {
  start();
  enable_motors();
  ASSERT_TRUE(drive({.xspeed = 400}, [](SegwayRmpEmulator& e) { return e.commanded_speed() > 0.3; }));
  EXPECT_TRUE(eventually(
      [&] {
        write_command(position(), protocol::PositionCommand{.xspeed = 400});
        return !devices.log.first_with({"lost the robot"}, 10ms).empty();
      },
      6s))
      << devices.log.all();
  EXPECT_FALSE(position().available());
  // At least once: a slow run may also have let the watchdog stop it
  // between two of the commands above.
  EXPECT_TRUE(robot.wait_until([](SegwayRmpEmulator& e) { return e.watchdog_stops() >= 1; }));
  EXPECT_FALSE(devices.log.first_with({"the robot is back"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(position(), 2)) << devices.log.all();
  EXPECT_EQ(counter(position().driver(), "reconnects"), 1u);
}

struct SegwayRmpNoisyTest : SegwayRmpDriverTest {
  SegwayRmpNoisyTest() : SegwayRmpDriverTest({.tcp = false, .symlink = {}, .faults = noisy()}) {}
  static emulators::FaultPlan noisy() {
    emulators::FaultPlan plan;
    plan.garbage = 0.05;
    plan.truncate = 0.02;
    plan.drop = 0.005;
    plan.bad_checksum = 0.1;  // slcan has none: left alone
    return plan;
  }
};

TEST_F(SegwayRmpNoisyTest, NoiseAndCutFramesCostOnlyTheirStatusSets) {
  start();
  enable_motors();
  ASSERT_TRUE(drive({.xspeed = 300}, [](SegwayRmpEmulator& e) { return e.status().fore_aft_displacement > 6000; }));
  EXPECT_GT(robot.runner().stats().faults.garbage_runs, 5u);
  EXPECT_GT(counter(position().driver(), "resyncs"), 0u);
  EXPECT_EQ(devices.log.count("lost the robot"), 0u) << devices.log.all();
}

struct SegwayRmpReplugTest : SegwayRmpDriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("segwayrmp-replug");
    return {.tcp = false, .symlink = scratch.file("ttyCAN"), .faults = {}};
  }
  SegwayRmpReplugTest() : SegwayRmpDriverTest(on_a_symlink()) {}
};

TEST_F(SegwayRmpReplugTest, AnAdapterUnpluggedAndBackIsOpenedAgain) {
  start();
  ASSERT_TRUE(next_data<protocol::PositionData>(position()));
  robot.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the robot"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"the robot is back"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(position(), 2)) << devices.log.all();
  EXPECT_TRUE(robot.with([](SegwayRmpEmulator& e) { return e.channel_open(); }));
}

struct SegwayRmpSlowStartTest : SegwayRmpDriverTest {
  SegwayRmpSlowStartTest() : SegwayRmpDriverTest({.tcp = false, .symlink = {}, .faults = slow()}) {}
  static emulators::FaultPlan slow() {
    emulators::FaultPlan plan;
    plan.silent_start = std::chrono::seconds(30);
    return plan;
  }
};

TEST_F(SegwayRmpSlowStartTest, AnAdapterThatNeverAnswersFailsWithinItsTimeout) {
  const auto began = std::chrono::steady_clock::now();
  devices.load("position:0 ( driver \"segwayrmp\" canio \"slcan\" port \"$PORT\" )\n", robot.port());
  EXPECT_FALSE(position().subscribe());
  EXPECT_LT(std::chrono::steady_clock::now() - began, 5s);
}

struct SegwayRmpWakingTest : SegwayRmpDriverTest {
  SegwayRmpWakingTest() : SegwayRmpDriverTest({.tcp = false, .symlink = {}, .faults = waking()}) {}
  static emulators::FaultPlan waking() {
    emulators::FaultPlan plan;
    plan.slow_start = std::chrono::milliseconds(400);
    return plan;
  }
};

// An adapter deaf and mute for 0.4 s each time the port opens (the kit's
// slow-start): the channel is asked for again, and the robot reports.
TEST_F(SegwayRmpWakingTest, AnAdapterSlowToWakeIsAskedAgainAndTheRobotReports) {
  start();
  EXPECT_TRUE(more_data(position(), 3)) << devices.log.all();
}

}  // namespace segwayrmp_driver_test
}  // namespace playerkit::drivers::testing
