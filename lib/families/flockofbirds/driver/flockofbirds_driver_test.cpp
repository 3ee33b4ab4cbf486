// The flockofbirds driver against the emulated bird on a real
// pseudo-terminal, through the kit's driver harness: start-up as 1.5's
// driver does it, the position3d mapping, both scalings, options, a bird
// left streaming, unplugged and back, and every fault the kit injects.

#include "families/flockofbirds/driver/flockofbirds_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "drivers/builtin.hpp"
#include "drivers/driver_harness_test_support.hpp"
#include "families/flockofbirds/driver/flockofbirds_options.hpp"
#include "families/flockofbirds/emulator/flock_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position3d.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace flockofbirds_driver_test {

using emulators::FlockEmulator;
using emulators::FlockEmulatorOptions;
using protocol::Position3dData;
namespace fob = hardware::flockofbirds;

// The pose of the sheet's worked example (flockofbirds.md §1.1), held still.
FlockEmulatorOptions at_the_sheets_pose(int baud = 115200) {
  FlockEmulatorOptions options;
  options.trajectory = emulators::BirdTrajectory::parse("0 304.8 -152.4 76.2 90 -45 10\n", false);
  options.baud = baud;
  return options;
}

emulators::FaultPlan fault(double emulators::FaultPlan::*kind, double probability) {
  emulators::FaultPlan plan;
  plan.*kind = probability;
  return plan;
}

struct FlockDriverTest : ::testing::Test {
  explicit FlockDriverTest(LineOptions line = {}, FlockEmulatorOptions options = at_the_sheets_pose())
      : bird([options] { return std::make_unique<FlockEmulator>(options); }, std::move(line)) {}

  core::Device& tracker() { return devices.device(protocol::kPosition3dCode); }
  void load(const std::string& extra = "") {
    devices.load("position3d:0 ( driver \"flockofbirds\" port \"$PORT\" " + extra + ")\n", bird.port());
  }
  void start(const std::string& extra = "") {
    load(extra);
    ASSERT_TRUE(tracker().subscribe()) << devices.log.all();
  }
  // Data at the sheet's pose, as the driver maps it.
  static bool at_sheets_pose(const Position3dData& d) {
    return d.xpos == 305 && d.ypos == -152 && d.zpos == -76 && d.yaw == 324000 && d.pitch == 1134000 &&
           d.roll == 35991;
  }

  EmulatedLine<FlockEmulator> bird;
  ConfiguredDevices devices;
};

TEST_F(FlockDriverTest, StartsTheBirdAsPlayerDidAndPublishesItsPose) {
  start();
  EXPECT_TRUE(bird.wait_until([](FlockEmulator& e) { return e.streaming(); }));
  const auto data = next_data<Position3dData>(tracker());
  ASSERT_TRUE(data) << devices.log.all();
  EXPECT_TRUE(at_sheets_pose(*data)) << data->xpos << " " << data->ypos << " " << data->zpos << " " << data->yaw
                                     << " " << data->pitch << " " << data->roll;
  EXPECT_EQ(data->xspeed, 0);
  EXPECT_EQ(data->stall, 0);
  // Records stream at the bird's rate: many publications a second.
  EXPECT_TRUE(more_data(tracker(), 20, 2s));
  EXPECT_GT(counter(tracker().driver(), "records"), 20u);
}

TEST_F(FlockDriverTest, LeavesTheBirdInPointModeAtShutdown) {
  start();
  ASSERT_TRUE(next_data<Position3dData>(tracker()));
  tracker().unsubscribe();
  EXPECT_TRUE(bird.wait_until([](FlockEmulator& e) { return !e.streaming(); })) << devices.log.all();
}

TEST_F(FlockDriverTest, AcceptsCommandsAndNacksEveryRequestAs15Did) {
  start();
  write_command(tracker(), protocol::Position3dCommand{.xpos = 1, .ypos = 2, .zpos = 3, .roll = 0, .pitch = 0, .yaw = 0,
                                                       .xspeed = 0, .yspeed = 0, .zspeed = 0, .rollspeed = 0,
                                                       .pitchspeed = 0, .yawspeed = 0});
  EXPECT_TRUE(nacked(ask(tracker(), protocol::Position3dPowerConfig{.request = protocol::kPosition3dMotorPowerReq, .value = 1})));
  EXPECT_TRUE(nacked(ask(tracker(), std::vector<std::uint8_t>{protocol::kPosition3dGetGeomReq})));
  EXPECT_TRUE(more_data(tracker(), 5));
}

TEST_F(FlockDriverTest, ReadsPlayer15sTermiosBaudConstants) {
  EXPECT_EQ(flockofbirds::baud_from_option(4098), 115200);
  EXPECT_EQ(flockofbirds::baud_from_option(4097), 57600);
  EXPECT_EQ(flockofbirds::baud_from_option(13), 9600);
  EXPECT_EQ(flockofbirds::baud_from_option(9600), 9600);
  EXPECT_EQ(flockofbirds::baud_from_option(16), 0);
  EXPECT_EQ(flockofbirds::baud_from_option(115201), 0);
  start("baudrate 4098");  // 1.5's form: B115200's value
  EXPECT_TRUE(next_data<Position3dData>(tracker()));
}

TEST(FlockOptions, BadValuesAreRefusedAtTheirPlace) {
  const std::string bad_baud = config_error_of("position3d:0 ( driver \"flockofbirds\" port \"/tmp/bird\" baudrate 1000 )\n");
  EXPECT_NE(bad_baud.find(":1:64: flockofbirds: baudrate must be 2400"), std::string::npos) << bad_baud;
  const std::string bad_port = config_error_of("position3d:0 ( driver \"flockofbirds\" port \"tcp:localhost\" )\n");
  EXPECT_NE(bad_port.find(":1:43: flockofbirds: port is not a serial port"), std::string::npos) << bad_port;
}

TEST(FlockOptions, TheReadmeTableIsGeneratedFromTheSchema) {
  EXPECT_EQ(readme_options_table(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/flockofbirds/README.md",
                                 "flockofbirds"),
            flockofbirds::flockofbirds_option_schema().markdown());
}

TEST(FlockOptions, RegisteredAsPlayer15DidWithItsDocs) {
  core::DriverRegistry registry;
  register_builtin_drivers(registry);
  const core::DriverSpec* spec = registry.find("flockofbirds");
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(spec->interfaces, std::vector<std::uint16_t>{protocol::kPosition3dCode});
  EXPECT_EQ(spec->access, protocol::Access::kAll);
  EXPECT_EQ(spec->family, "flockofbirds");
  EXPECT_EQ(spec->doc.manual_section, "7.10");
  EXPECT_TRUE(spec->doc.needs_hardware);
  EXPECT_EQ(spec->doc.option_rows().size(), 2u);
}

struct FlockAt9600Test : FlockDriverTest {
  FlockAt9600Test() : FlockDriverTest({}, at_the_sheets_pose(9600)) {}
};

TEST_F(FlockAt9600Test, ABirdSwitchedTo9600AnswersOnlyAt9600) {
  load();
  EXPECT_FALSE(tracker().subscribe());  // 115200 by default: the bird hears noise
  EXPECT_FALSE(devices.log.first_with({"baudrate 115200"}).empty()) << devices.log.all();
}

TEST_F(FlockAt9600Test, ABirdSwitchedTo9600WithPlayers15Constant) {
  start("baudrate 13");
  const auto data = next_data<Position3dData>(tracker());
  ASSERT_TRUE(data);
  EXPECT_TRUE(at_sheets_pose(*data));
}

struct Flock72InchTest : FlockDriverTest {
  static FlockEmulatorOptions far_out() {
    FlockEmulatorOptions options;
    options.trajectory = emulators::BirdTrajectory::parse("0 1200 -1500 300 -90 0 0\n", false);
    options.scaling = fob::PositionScaling::inches_72;
    return options;
  }
  Flock72InchTest() : FlockDriverTest({}, far_out()) {}
};

TEST_F(Flock72InchTest, ReadsTheScalingBeforeTheFirstRecord) {
  start();
  const auto data = next_data<Position3dData>(tracker());
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->xpos, 1200, 1);
  EXPECT_NEAR(data->ypos, -1500, 1);
  EXPECT_NEAR(data->zpos, -300, 1);
  EXPECT_EQ(data->yaw, 270 * 3600);
}

struct FlockMovingTest : FlockDriverTest {
  FlockMovingTest() : FlockDriverTest({}, FlockEmulatorOptions{}) {}
};

TEST_F(FlockMovingTest, FollowsTheBuiltInMotion) {
  start();
  const auto first = next_data<Position3dData>(tracker());
  ASSERT_TRUE(first);
  const auto later = data_when<Position3dData>(tracker(), [&](const auto& d) { return d.yaw != first->yaw; });
  ASSERT_TRUE(later);
  EXPECT_NE(later->yaw, first->yaw);
  EXPECT_GE(later->xpos, 199);
  EXPECT_LE(later->xpos, 401);
}

TEST_F(FlockDriverTest, StopsAStreamLeftRunningBeforeAskingTheScaling) {
  // A host that died without POINT left the bird streaming.
  bird.with([](FlockEmulator& e) {
    const std::vector<std::uint8_t> stream{0x40};
    e.receive(stream, std::chrono::nanoseconds(0), 0);
    return 0;
  });
  ASSERT_TRUE(bird.wait_until([](FlockEmulator& e) { return e.records_sent() > 5; }));
  start();
  const auto data = next_data<Position3dData>(tracker());
  ASSERT_TRUE(data);
  EXPECT_TRUE(at_sheets_pose(*data));
}

TEST_F(FlockDriverTest, RefusesTheSubscriptionWhenNothingAnswers) {
  bird.replug(false);
  load();
  EXPECT_FALSE(tracker().subscribe());
}

// A bird whose EXAMINE VALUE 3 answer is neither 36" nor 72".
class OddScalingBird final : public emulators::DeviceEmulator {
 public:
  void receive(std::span<const std::uint8_t> bytes, emulators::Duration, int) override {
    for (const std::uint8_t byte : bytes) {
      if (byte == 0x42) out_.push_back({{0x80, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}, false});
      if (byte == 0x03) out_.push_back({{0x02, 0x00}, false});
    }
  }
  void advance(emulators::Duration) override {}
  [[nodiscard]] emulators::Duration next_deadline() const override { return emulators::Duration::max(); }
  std::vector<emulators::Telegram> take_output() override { return std::exchange(out_, {}); }
  [[nodiscard]] std::string describe() const override { return "a bird with an odd scaling"; }

 private:
  std::vector<emulators::Telegram> out_;
};

TEST(FlockOddScaling, AScalingNeither36Nor72InchesRefusesTheSubscriptionNamingIt) {
  EmulatedLine<OddScalingBird> bird([] { return std::make_unique<OddScalingBird>(); });
  ConfiguredDevices devices;
  devices.load("position3d:0 ( driver \"flockofbirds\" port \"$PORT\" )\n", bird.port());
  EXPECT_FALSE(devices.device(protocol::kPosition3dCode).subscribe());
  EXPECT_FALSE(devices.log.first_with({"position scaling with 02 00"}).empty()) << devices.log.all();
}

struct FlockReplugTest : FlockDriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("flockofbirds-replug");
    return {.tcp = false, .symlink = scratch.file("ttyBIRD"), .faults = {}};
  }
  FlockReplugTest() : FlockDriverTest(on_a_symlink()) {}
};

TEST_F(FlockReplugTest, ABirdUnpluggedAndBackIsFoundAgain) {
  start();
  ASSERT_TRUE(next_data<Position3dData>(tracker()));
  bird.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the Flock of Birds"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(tracker(), 5)) << devices.log.all();
  EXPECT_TRUE(bird.with([](FlockEmulator& e) { return e.streaming(); }));
}

// The faults of the kit, one line each.
struct FlockFaultTest : FlockDriverTest {
  explicit FlockFaultTest(emulators::FaultPlan plan) : FlockDriverTest({.tcp = false, .symlink = {}, .faults = plan}) {}
  // Data keeps coming at the sheet's pose, and the bird is never lost.
  void keeps_tracking() {
    start();
    for (int i = 0; i < 30; ++i) {
      const auto data = next_data<Position3dData>(tracker());
      ASSERT_TRUE(data) << devices.log.all();
      EXPECT_TRUE(at_sheets_pose(*data)) << data->xpos << " " << data->ypos << " " << data->roll;
    }
    EXPECT_EQ(devices.log.count("lost the Flock of Birds"), 0u) << devices.log.all();
  }
};

struct FlockGarbageTest : FlockFaultTest {
  FlockGarbageTest() : FlockFaultTest(fault(&emulators::FaultPlan::garbage, 0.2)) {}
};
// Noise before records: a stray byte with bit 7 set starts a false record,
// which the next real record's phasing bit cuts short.
TEST_F(FlockGarbageTest, NoiseBetweenRecordsLosesNoRecordItDoesNotHit) {
  keeps_tracking();
  EXPECT_GT(bird.runner().stats().faults.garbage_runs, 5u);
  EXPECT_GT(counter(tracker().driver(), "resyncs"), 0u);
}

struct FlockTruncateTest : FlockFaultTest {
  FlockTruncateTest() : FlockFaultTest(fault(&emulators::FaultPlan::truncate, 0.2)) {}
};
TEST_F(FlockTruncateTest, ARecordCutShortIsDroppedNotMisread) {
  keeps_tracking();
  EXPECT_GT(bird.runner().stats().faults.truncated, 5u);
}

struct FlockDropTest : FlockFaultTest {
  FlockDropTest() : FlockFaultTest(fault(&emulators::FaultPlan::drop, 0.01)) {}
};
TEST_F(FlockDropTest, ARecordMissingAByteIsDroppedNotMisread) {
  keeps_tracking();
  EXPECT_GT(bird.runner().stats().faults.dropped_bytes, 0u);
}

struct FlockBadChecksumTest : FlockFaultTest {
  FlockBadChecksumTest() : FlockFaultTest(fault(&emulators::FaultPlan::bad_checksum, 0.5)) {}
};
// Records carry no checksum (flockofbirds.md §1): the fault finds none to spoil.
TEST_F(FlockBadChecksumTest, RecordsHaveNoChecksumToSpoil) {
  keeps_tracking();
  EXPECT_EQ(bird.runner().stats().faults.bad_checksums, 0u);
}

struct FlockSilentStartTest : FlockFaultTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan plan;
    plan.silent_start = std::chrono::milliseconds(700);
    return plan;
  }
  FlockSilentStartTest() : FlockFaultTest(plan()) {}
};
// A bird still booting: POINT is asked again until it answers.
TEST_F(FlockSilentStartTest, ABirdSlowToBootIsAskedAgain) {
  keeps_tracking();
  EXPECT_GE(counter(tracker().driver(), "retries"), 1u);
}

struct FlockSlowStartTest : FlockFaultTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan plan;
    plan.slow_start = std::chrono::milliseconds(700);
    return plan;
  }
  FlockSlowStartTest() : FlockFaultTest(plan()) {}
};
// Deaf for a while after every open (a bird powered with its adapter).
TEST_F(FlockSlowStartTest, ABirdDeafAfterEachOpenIsAskedAgain) {
  keeps_tracking();
  EXPECT_GE(counter(tracker().driver(), "retries"), 1u);
}

struct FlockVanishTest : FlockFaultTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan plan;
    plan.vanish_at = std::chrono::seconds(1);
    plan.vanish_for = std::chrono::seconds(2);
    return plan;
  }
  FlockVanishTest() : FlockFaultTest(plan()) {}
};
// The line goes dead both ways for a while (the port stays): the stream's
// silence loses the bird, and it is started again when it answers.
TEST_F(FlockVanishTest, ABirdThatFallsSilentIsLostAndFoundAgain) {
  start();
  EXPECT_FALSE(devices.log.first_with({"lost the Flock of Birds", "no record"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(tracker().available());
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(tracker(), 5)) << devices.log.all();
  EXPECT_EQ(counter(tracker().driver(), "reconnects"), 1u);
  EXPECT_TRUE(at_sheets_pose(*latest<Position3dData>(tracker())));
}

}  // namespace flockofbirds_driver_test
}  // namespace playerkit::drivers::testing
