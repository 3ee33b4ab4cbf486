// The ptu46 driver against the emulated PTU-46 on a real pseudo-terminal,
// through the kit's driver harness: start-up as 1.5's driver does it, the
// ptz mapping both ways, both control modes, the unit's own commands, bad
// options, a unit unplugged and back, and a noisy line.

#include "families/ptu46/driver/ptu46_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/ptu46/driver/ptu46_options.hpp"
#include "families/ptu46/emulator/ptu46_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace {

using emulators::Ptu46Emulator;
using Axis = Ptu46Emulator::Axis;
using ControlMode = Ptu46Emulator::ControlMode;

// The default unit's resolution, 185.1428 arc-seconds, in degrees.
constexpr double kDegreesPerPosition = 185.1428 / 3600.0;

struct Ptu46DriverTest : ::testing::Test {
  explicit Ptu46DriverTest(LineOptions options = {})
      : unit([] { return std::make_unique<Ptu46Emulator>(); }, std::move(options)) {}

  core::Device& ptz() { return devices.device(protocol::kPtzCode); }
  void start(const std::string& extra = "") {
    devices.load("ptz:0 ( driver \"ptu46\" port \"$PORT\" " + extra + ")\n", unit.port());
    ASSERT_TRUE(ptz().subscribe()) << devices.log.all();
  }

  EmulatedLine<Ptu46Emulator> unit;
  ConfiguredDevices devices;
};

TEST_F(Ptu46DriverTest, StartsTheUnitAsPlayerDidAndPublishesItsState) {
  start();
  EXPECT_TRUE(unit.with([](Ptu46Emulator& e) { return e.terse() && !e.echo(); }));
  EXPECT_EQ(unit.with([](Ptu46Emulator& e) { return e.mode(); }), ControlMode::independent);
  const auto data = next_data<protocol::PtzData>(ptz());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->pan, 0);
  EXPECT_EQ(data->tilt, 0);
  EXPECT_EQ(data->zoom, 0);
  EXPECT_EQ(data->panspeed, 51);  // the power-up 1000 positions/s (ptu46.md §2.2's example)
  EXPECT_EQ(data->tiltspeed, 51);
}

TEST_F(Ptu46DriverTest, PointsTheUnitWhereTheClientSaysAndReportsWhereItGot) {
  start();
  write_command(ptz(), protocol::PtzCommand{.pan = 30, .tilt = -10, .zoom = 0, .panspeed = 50, .tiltspeed = 0});
  // ptu46.md's worked example: 30 deg -> pp583, 50 deg/s -> ps972; -10 deg truncates to -194.
  ASSERT_TRUE(unit.wait_until([](Ptu46Emulator& e) { return e.target(Axis::pan) == 583; })) << devices.log.all();
  EXPECT_TRUE(unit.wait_until([](Ptu46Emulator& e) { return e.target(Axis::tilt) == -194; }));
  EXPECT_EQ(unit.with([](Ptu46Emulator& e) { return e.speed(Axis::pan); }), 972);
  const auto data = data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan == 30 && d.tilt == -10; });
  ASSERT_TRUE(data);
  EXPECT_EQ(data->pan, 30);
  EXPECT_EQ(data->tilt, -10);
  EXPECT_EQ(data->panspeed, 50);
}

TEST_F(Ptu46DriverTest, ClampsATargetBeyondTheUnitsReachInsteadOfRetryingIt) {
  start();
  write_command(ptz(), protocol::PtzCommand{.pan = 170, .tilt = -80, .zoom = 0, .panspeed = 0, .tiltspeed = 0});
  EXPECT_TRUE(unit.wait_until([](Ptu46Emulator& e) { return e.target(Axis::pan) == 3090 && e.target(Axis::tilt) == -907; }));
  EXPECT_EQ(devices.log.count("refused"), 0u) << devices.log.all();
  EXPECT_EQ(counter(ptz().driver(), "refused_commands"), 0u);
}

TEST_F(Ptu46DriverTest, VelocityControlDrivesTheAxesBySignedSpeeds) {
  start();
  EXPECT_TRUE(acked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq,
                                                               .mode = protocol::kPtzVelocityControl})));
  EXPECT_EQ(unit.with([](Ptu46Emulator& e) { return e.mode(); }), ControlMode::pure_velocity);
  write_command(ptz(), protocol::PtzCommand{.pan = 0, .tilt = 0, .zoom = 0, .panspeed = 0, .tiltspeed = -20});
  // -20 deg/s: -388.9 positions/s, truncated.
  EXPECT_TRUE(unit.wait_until([](Ptu46Emulator& e) { return e.speed(Axis::tilt) == -388; })) << devices.log.all();
  EXPECT_TRUE(data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.tilt < -5; }).value_or(protocol::PtzData{}).tilt < -5);
  // Asking for the mode it is in is no failure; a mode that does not exist is.
  EXPECT_TRUE(acked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq,
                                                               .mode = protocol::kPtzVelocityControl})));
  EXPECT_TRUE(nacked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq, .mode = 7})));
  EXPECT_TRUE(acked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq,
                                                               .mode = protocol::kPtzPositionControl})));
  EXPECT_EQ(unit.with([](Ptu46Emulator& e) { return e.mode(); }), ControlMode::independent);
}

TEST_F(Ptu46DriverTest, PassesTheUnitsOwnCommandsThroughGenericConfig) {
  start();
  protocol::PtzGenericConfig command;
  command.subtype = protocol::kPtzGenericConfigReq;
  const std::string text = "pr";
  command.length = static_cast<std::uint16_t>(text.size());
  std::copy(text.begin(), text.end(), command.config.begin());
  const auto reply = ask(ptz(), command);
  ASSERT_TRUE(acked(reply));
  const auto answer = protocol::decode<protocol::PtzGenericConfig>(reply->payload);
  EXPECT_EQ(std::string(answer.config.begin(), answer.config.begin() + answer.length), "* 185.1428");
}

TEST_F(Ptu46DriverTest, AnswersEveryRequestEvenOnesItDoesNotKnow) {
  start();
  EXPECT_TRUE(nacked(ask(ptz(), std::vector<std::uint8_t>{9, 0})));  // 1.5 left these unanswered
}

TEST_F(Ptu46DriverTest, ReadsPlayer15sTermiosBaudConstants) {
  EXPECT_EQ(ptu46::baud_from_option(13), 9600);
  EXPECT_EQ(ptu46::baud_from_option(15), 38400);
  EXPECT_EQ(ptu46::baud_from_option(19200), 19200);
  EXPECT_EQ(ptu46::baud_from_option(9601), 0);
  start("baudrate 13");
  EXPECT_TRUE(next_data<protocol::PtzData>(ptz()));
}

TEST(Ptu46Options, BadValuesAreRefusedAtTheirPlace) {
  EXPECT_NE(config_error_of("ptz:0 ( driver \"ptu46\" port \"/tmp/ptu\" baudrate 9601 )\n").find(":1:49: ptu46: baudrate must be 600"),
            std::string::npos)
      << config_error_of("ptz:0 ( driver \"ptu46\" port \"/tmp/ptu\" baudrate 9601 )\n");
  EXPECT_NE(config_error_of("ptz:0 ( driver \"ptu46\" port \"tcp:localhost\" )\n").find(":1:29: ptu46: port is not a serial port"),
            std::string::npos)
      << config_error_of("ptz:0 ( driver \"ptu46\" port \"tcp:localhost\" )\n");
}

TEST_F(Ptu46DriverTest, RefusesTheSubscriptionWhenNothingAnswers) {
  unit.replug(false);
  devices.load("ptz:0 ( driver \"ptu46\" port \"" + unit.port() + "\" )\n");
  EXPECT_FALSE(ptz().subscribe());
}

struct Ptu46ReplugTest : Ptu46DriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("ptu46-replug");
    return {.tcp = false, .symlink = scratch.file("ttyPTU"), .faults = {}};
  }
  Ptu46ReplugTest() : Ptu46DriverTest(on_a_symlink()) {}
};

TEST_F(Ptu46ReplugTest, AUnitUnpluggedAndBackIsFoundAgain) {
  start();
  ASSERT_TRUE(next_data<protocol::PtzData>(ptz()));
  unit.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the PTU-46"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(ptz(), 2)) << devices.log.all();
  EXPECT_TRUE(unit.with([](Ptu46Emulator& e) { return e.terse(); }));  // started anew
}

struct Ptu46SilentSpellTest : Ptu46DriverTest {
  Ptu46SilentSpellTest() : Ptu46DriverTest({.tcp = false, .symlink = {}, .faults = silent_spell()}) {}
  static emulators::FaultPlan silent_spell() {
    emulators::FaultPlan plan;
    plan.vanish_at = std::chrono::seconds(1);
    plan.vanish_for = std::chrono::seconds(2);
    return plan;
  }
};

// The line goes dead both ways for a while (the port stays): the unit's
// silence loses it, and it is started again when it answers.
TEST_F(Ptu46SilentSpellTest, AUnitThatFallsSilentIsLostAndFoundAgain) {
  start();
  EXPECT_FALSE(devices.log.first_with({"lost the PTU-46", "no reply"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(ptz().available());
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(ptz(), 2)) << devices.log.all();
  EXPECT_EQ(counter(ptz().driver(), "reconnects"), 1u);
}

struct Ptu46NoisyLineTest : Ptu46DriverTest {
  Ptu46NoisyLineTest() : Ptu46DriverTest({.tcp = false, .symlink = {}, .faults = noisy()}) {}
  static emulators::FaultPlan noisy() {
    emulators::FaultPlan plan;
    plan.garbage = 0.3;
    return plan;
  }
};

// Noise lands inside reply lines (no line format can tell it from text): the
// reply is found behind it, and a reply lost to it is asked for again.
TEST_F(Ptu46NoisyLineTest, NoiseBeforeRepliesLosesNothing) {
  start();
  write_command(ptz(), protocol::PtzCommand{.pan = -45, .tilt = 20, .zoom = 0, .panspeed = 100, .tiltspeed = 100});
  const auto data = data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan == -45 && d.tilt == 20; },
                                                 10s);
  ASSERT_TRUE(data);
  EXPECT_EQ(data->pan, -45);
  EXPECT_GT(unit.runner().stats().faults.garbage_runs, 10u);
  EXPECT_EQ(devices.log.count("lost the PTU-46"), 0u) << devices.log.all();
}

}  // namespace
}  // namespace playerkit::drivers::testing
