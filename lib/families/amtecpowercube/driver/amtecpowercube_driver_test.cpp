// The amtecpowercube driver against the emulated wrist on a real
// pseudo-terminal, through the kit's driver harness: start-up as 1.5's
// driver does it (both modules found, reset, homed), the ptz mapping both
// ways, both control modes, the options, homing at shutdown, a module
// error, and each fault of the kit.

#include "families/amtecpowercube/driver/amtecpowercube_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/amtecpowercube/driver/powercube_options.hpp"
#include "families/amtecpowercube/emulator/powercube_emulator.hpp"
#include "families/amtecpowercube/protocol/powercube_units.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace {

using emulators::PowercubeEmulator;
using emulators::PowercubeEmulatorOptions;
using Module = PowercubeEmulator::Module;
namespace pc = hardware::powercube;

double module_degrees(PowercubeEmulator& e, Module module) { return pc::degrees(e.position(module)); }

struct PowercubeDriverTest : ::testing::Test {
  explicit PowercubeDriverTest(LineOptions options = {}, PowercubeEmulatorOptions wrist = {.pan_start = -5, .tilt_start = 3})
      : unit([wrist] { return std::make_unique<PowercubeEmulator>(wrist); }, std::move(options)) {}

  core::Device& ptz() { return devices.device(protocol::kPtzCode); }
  void start(const std::string& extra = "") {
    devices.load("ptz:0 ( driver \"amtecpowercube\" port \"$PORT\" " + extra + ")\n", unit.port());
    ASSERT_TRUE(ptz().subscribe()) << devices.log.all();
  }
  void point(int pan, int tilt, int panspeed = 0, int tiltspeed = 0) {
    write_command(ptz(), protocol::PtzCommand{.pan = static_cast<std::int16_t>(pan),
                                              .tilt = static_cast<std::int16_t>(tilt),
                                              .zoom = 0,
                                              .panspeed = static_cast<std::int16_t>(panspeed),
                                              .tiltspeed = static_cast<std::int16_t>(tiltspeed)});
  }
  std::optional<core::Reply> control_mode(std::uint8_t mode) {
    return ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq, .mode = mode});
  }

  EmulatedLine<PowercubeEmulator> unit;
  ConfiguredDevices devices;
};

TEST_F(PowercubeDriverTest, FindsResetsAndHomesBothModulesThenPublishes) {
  start();
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.state(Module::pan); }), pc::state_bit::homed);
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.state(Module::tilt); }), pc::state_bit::homed);
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.homings(Module::pan) + e.homings(Module::tilt); }), 2u);
  const auto data = next_data<protocol::PtzData>(ptz());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->pan, 0);
  EXPECT_EQ(data->tilt, 0);
  EXPECT_EQ(data->zoom, 0);
  EXPECT_EQ(data->panspeed, 0);
}

TEST_F(PowercubeDriverTest, PointsTheWristAndReportsWhereItGot) {
  start();
  point(30, -20);
  // Player's pan counts counter-clockwise, the module clockwise; 30 deg at 40 deg/s takes 750 ms.
  // The tilt's step follows the pan's on the line: both are waited for.
  ASSERT_TRUE(unit.wait_until([](PowercubeEmulator& e) {
    return e.step_time(Module::pan) == 750 && e.step_time(Module::tilt) == 500;
  })) << devices.log.all();
  EXPECT_NEAR(unit.with([](PowercubeEmulator& e) { return pc::degrees(e.target(Module::pan)); }), -30, 1e-4);
  const auto moving = data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan > 5 && d.pan < 25; });
  ASSERT_TRUE(moving);
  EXPECT_GT(moving->panspeed, 0);
  const auto data = data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan == 30 && d.tilt == -20; });
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return std::fabs(module_degrees(e, Module::pan) + 30) < 1e-4; }));
  EXPECT_TRUE(more_data(ptz(), 2));  // read where it stopped
  // The same command again moves nothing; a speed with it times the move.
  const auto moves = counter(ptz().driver(), "moves");
  point(30, -20);
  point(-60, -20, 30);
  ASSERT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return e.step_time(Module::pan) == 3000; }));
  EXPECT_TRUE(eventually([&] { return counter(ptz().driver(), "moves") == moves + 1; }));
  EXPECT_EQ(counter(ptz().driver(), "moves"), moves + 1);
}

TEST_F(PowercubeDriverTest, KeepsTargetsWithinTheLimitsTheModulesReport) {
  start();
  point(-175, 120);  // the modules reach -170..170 and -110..110
  ASSERT_TRUE(unit.wait_until([](PowercubeEmulator& e) {
    return std::fabs(pc::degrees(e.target(Module::pan)) - 170) < 1e-4 &&
           std::fabs(pc::degrees(e.target(Module::tilt)) - 110) < 1e-4;
  })) << devices.log.all();
  // Timed for the distance it will really go: 170 deg at 40 deg/s.
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.step_time(Module::pan); }), 4250);
}

TEST_F(PowercubeDriverTest, TheSpeedOptionTimesMovesAndBoundsVelocities) {
  start("speed 60 home 2");  // 1.5 took any integer for home
  point(0, 30);
  EXPECT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return e.step_time(Module::tilt) == 500; })) << devices.log.all();
  ASSERT_TRUE(acked(control_mode(protocol::kPtzVelocityControl)));
  point(0, 0, 0, 500);  // a speed above `speed` is `speed`
  EXPECT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return std::fabs(pc::degrees(e.target(Module::tilt)) - 60) < 1e-4; }))
      << devices.log.all();
}

TEST_F(PowercubeDriverTest, VelocityControlDrivesTheModulesAtTheGivenSpeeds) {
  start();
  ASSERT_TRUE(acked(control_mode(protocol::kPtzVelocityControl)));
  point(0, 0, 20, -100);
  ASSERT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return std::fabs(pc::degrees(e.target(Module::pan)) + 20) < 1e-4; }))
      << devices.log.all();
  // -100 deg/s is beyond `speed` (40).
  EXPECT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return std::fabs(pc::degrees(e.target(Module::tilt)) + 40) < 1e-4; }));
  const auto data = data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.panspeed == 20 && d.tiltspeed == -40; });
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_TRUE(data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan > 5 && d.tilt < -5; }));
  // The mode it is in is no failure; a mode that does not exist, or a request of another size, is.
  EXPECT_TRUE(acked(control_mode(protocol::kPtzVelocityControl)));
  EXPECT_TRUE(nacked(control_mode(7)));
  EXPECT_TRUE(nacked(ask(ptz(), std::vector<std::uint8_t>{protocol::kPtzControlModeReq, 1, 0})));
  // Back to position control: both modules stop where they are.
  ASSERT_TRUE(acked(control_mode(protocol::kPtzPositionControl)));
  EXPECT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return e.velocity(Module::pan) == 0 && e.velocity(Module::tilt) == 0; }));
  const auto held = unit.with([](PowercubeEmulator& e) { return module_degrees(e, Module::pan); });
  EXPECT_LT(held, -5);
  EXPECT_TRUE(more_data(ptz(), 3));
  EXPECT_NEAR(unit.with([](PowercubeEmulator& e) { return module_degrees(e, Module::pan); }), held, 1e-3);
}

TEST_F(PowercubeDriverTest, AnswersEveryRequestEvenOnesItDoesNotKnow) {
  start();
  EXPECT_TRUE(nacked(ask(ptz(), std::vector<std::uint8_t>{9, 0})));
  protocol::PtzGenericConfig generic;
  generic.subtype = protocol::kPtzGenericConfigReq;
  generic.length = 1;
  EXPECT_TRUE(nacked(ask(ptz(), generic)));
}

TEST_F(PowercubeDriverTest, HaltsAtShutdownAndHomesWhenAsked) {
  start();
  point(45, 0);
  ASSERT_TRUE(data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan == 45; }));
  ASSERT_TRUE(unit.wait_until([](PowercubeEmulator& e) { return std::fabs(module_degrees(e, Module::pan) + 45) < 1e-4; }));
  ptz().unsubscribe();
  EXPECT_TRUE(unit.with([](PowercubeEmulator& e) { return (e.state(Module::pan) & pc::state_bit::halted) != 0; }));
  EXPECT_NEAR(unit.with([](PowercubeEmulator& e) { return module_degrees(e, Module::pan); }), -45, 1e-4);
}

struct PowercubeHomeTest : PowercubeDriverTest {};

TEST_F(PowercubeHomeTest, HomeOneHomesBothModulesAgainAtShutdown) {
  start("home 1");
  point(-45, 30);
  ASSERT_TRUE(data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan == -45 && d.tilt == 30; }));
  ptz().unsubscribe();
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.homings(Module::pan) + e.homings(Module::tilt); }), 4u);
  EXPECT_NEAR(unit.with([](PowercubeEmulator& e) { return module_degrees(e, Module::pan); }), 0, 1e-6);
  EXPECT_NEAR(unit.with([](PowercubeEmulator& e) { return module_degrees(e, Module::tilt); }), 0, 1e-6);
}

TEST_F(PowercubeDriverTest, AModuleErrorIsLostAndTheWristStartedAgain) {
  start();
  ASSERT_TRUE(next_data<protocol::PtzData>(ptz()));
  unit.with([](PowercubeEmulator& e) {
    e.raise_error(Module::tilt);
    return 0;
  });
  EXPECT_FALSE(devices.log.first_with({"tilt module 11 reports an error"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.state(Module::tilt); }), pc::state_bit::homed);
  EXPECT_EQ(counter(ptz().driver(), "module_errors"), 1u);
  EXPECT_TRUE(more_data(ptz(), 2));
}

TEST(PowercubeOptions, BadValuesAreRefusedAtTheirPlace) {
  const std::string slow = config_error_of("ptz:0 ( driver \"amtecpowercube\" port \"/tmp/cube\" speed 0 )\n");
  EXPECT_NE(slow.find(":1:56: amtecpowercube: speed must be between 0.1 and 1000"), std::string::npos) << slow;
  const std::string port = config_error_of("ptz:0 ( driver \"amtecpowercube\" port \"tcp:localhost\" )\n");
  EXPECT_NE(port.find(":1:38: amtecpowercube: port"), std::string::npos) << port;
}

// The README's options table is the schema's own (between "<!-- options
// amtecpowercube -->" and "<!-- end options -->").
TEST(PowercubeOptions, TheReadmeTableIsTheSchemas) {
  EXPECT_EQ(readme_options_table(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/amtecpowercube/README.md",
                                 "amtecpowercube"),
            amtecpowercube::powercube_option_schema().markdown());
}

struct PowercubeTiltlessTest : PowercubeDriverTest {
  PowercubeTiltlessTest() : PowercubeDriverTest({}, {.tilt_present = false}) {}
};

TEST_F(PowercubeTiltlessTest, AWristMissingAModuleIsRefusedNamingIt) {
  devices.load("ptz:0 ( driver \"amtecpowercube\" port \"" + unit.port() + "\" )\n");
  EXPECT_FALSE(ptz().subscribe());
  EXPECT_FALSE(devices.log.first_with({"tilt module 11 does not answer"}).empty()) << devices.log.all();
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.homings(Module::pan); }), 0u);  // nothing moved
}

struct PowercubeReplugTest : PowercubeDriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("amtecpowercube-replug");
    return {.tcp = false, .symlink = scratch.file("ttyCUBE"), .faults = {}};
  }
  PowercubeReplugTest() : PowercubeDriverTest(on_a_symlink()) {}
};

TEST_F(PowercubeReplugTest, AWristUnpluggedAndBackIsFoundAndHomedAgain) {
  start();
  ASSERT_TRUE(next_data<protocol::PtzData>(ptz()));
  unit.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the PowerCube"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(ptz(), 2)) << devices.log.all();
  EXPECT_EQ(unit.with([](PowercubeEmulator& e) { return e.state(Module::pan); }), pc::state_bit::homed);
}

struct PowercubeFaultTest : PowercubeDriverTest {
  explicit PowercubeFaultTest(emulators::FaultPlan plan) : PowercubeDriverTest({.tcp = false, .symlink = {}, .faults = plan}) {}
};

struct PowercubeSilentSpellTest : PowercubeFaultTest {
  PowercubeSilentSpellTest() : PowercubeFaultTest({.vanish_at = 2s, .vanish_for = 2s}) {}
};

// The line goes dead both ways for a while (the port stays): the wrist's
// silence loses it, and it is found, reset and homed when it answers.
TEST_F(PowercubeSilentSpellTest, AWristThatFallsSilentIsLostAndFoundAgain) {
  start();
  EXPECT_FALSE(devices.log.first_with({"lost the PowerCube", "no reply"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(ptz().available());
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(ptz(), 2)) << devices.log.all();
  EXPECT_EQ(counter(ptz().driver(), "reconnects"), 1u);
}

struct PowercubeSlowStartTest : PowercubeFaultTest {
  PowercubeSlowStartTest() : PowercubeFaultTest({.silent_start = 3s}) {}
};

TEST_F(PowercubeSlowStartTest, AWristStillBootingIsRefusedThenFound) {
  devices.load("ptz:0 ( driver \"amtecpowercube\" port \"" + unit.port() + "\" )\n");
  EXPECT_FALSE(ptz().subscribe());
  EXPECT_FALSE(devices.log.first_with({"pan module 12 does not answer"}).empty()) << devices.log.all();
  ASSERT_TRUE(eventually([&] { return ptz().subscribe(); }, 10s)) << devices.log.all();
  EXPECT_TRUE(next_data<protocol::PtzData>(ptz()));
}

struct PowercubeNoisyLineTest : PowercubeFaultTest {
  PowercubeNoisyLineTest()
      : PowercubeFaultTest({.bad_checksum = 0.05, .garbage = 0.2, .truncate = 0.05, .drop = 0.001, .seed = 3}) {}
};

// Noise before frames, frames cut short or with their end corrupted, bytes
// lost: each damaged reply is asked for again; nothing is lost for it.
TEST_F(PowercubeNoisyLineTest, DamagedRepliesAreAskedForAgain) {
  start();
  point(-40, 25);
  const auto data = data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.pan == -40 && d.tilt == 25; }, 10s);
  ASSERT_TRUE(data) << devices.log.all();
  const auto faults = unit.runner().stats().faults;
  EXPECT_GT(faults.garbage_runs, 0u);
  EXPECT_GT(faults.garbage_runs + faults.bad_checksums + faults.truncated, 3u);
  EXPECT_GT(counter(ptz().driver(), "retries"), 0u);
}

}  // namespace
}  // namespace playerkit::drivers::testing
