// The cmucam2 drivers against the emulated camera on a real
// pseudo-terminal, through the kit's driver harness: blobs of the scene,
// the servos as ptz (one line for both devices), options as 1.5 wrote
// them, a camera unplugged and back, and the kit's faults.

#include "families/cmucam2/driver/cmucam2_driver.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/cmucam2/emulator/cmucam2_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/ptz.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace cmucam2_driver_test {

using namespace std::chrono_literals;
using emulators::Cmucam2Emulator;
using emulators::Cmucam2EmulatorOptions;

// The manual's form: devicepath, num_blobs, colorN (in the camera's R, G, B order).
const std::string kTwoColours =
    "num_blobs 2 color0 [200 240 16 60 16 60] color1 [16 60 180 240 16 60] ";

struct Cmucam2DriverTest : ::testing::Test {
  explicit Cmucam2DriverTest(Cmucam2EmulatorOptions options = {}, LineOptions line = {})
      : camera([options] { return std::make_unique<Cmucam2Emulator>(Cmucam2Emulator::default_scene(), options); },
               std::move(line)) {}

  core::Device& blobfinder() { return devices.device(protocol::kBlobfinderCode); }
  core::Device& ptz() { return devices.device(protocol::kPtzCode); }
  void load(const std::string& text) { devices.load(text, camera.port()); }

  EmulatedLine<Cmucam2Emulator> camera;
  ConfiguredDevices devices;
};

bool sees(const protocol::BlobfinderData& data, std::uint32_t color) {
  for (const auto& blob : data.blobs) {
    if (blob.color == color) return true;
  }
  return false;
}

TEST_F(Cmucam2DriverTest, ReportsTheBlobsOfTheConfiguredColours) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" " + kTwoColours + ")\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  EXPECT_TRUE(camera.with([](Cmucam2Emulator& e) { return e.poll_mode(); }));
  // Without a ptz device the servos are left where they are (1.5 never moved them).
  EXPECT_TRUE(more_data(blobfinder(), 2));
  EXPECT_EQ(camera.with([](Cmucam2Emulator& e) { return e.servo_target(0); }), Cmucam2Emulator::kServoCentre);
  const auto data = data_when<protocol::BlobfinderData>(blobfinder(), [](const auto& d) { return d.blobs.size() == 2; });
  ASSERT_TRUE(data) << devices.log.all();
  ASSERT_EQ(data->blobs.size(), 2u) << devices.log.all();
  EXPECT_EQ(data->width, 88);
  EXPECT_EQ(data->height, 143);
  EXPECT_EQ(data->header[0].num, 2);
  const auto& red = data->blobs[0];
  EXPECT_EQ(red.color, 0xdc2626u);  // the middle of color0's bounds
  EXPECT_NEAR(red.x, 26, 1);        // 10 degrees left of centre
  EXPECT_NEAR(red.y, 72, 1);
  EXPECT_LT(red.left, red.x);
  EXPECT_GT(red.right, red.x);
  EXPECT_LT(red.top, red.y);  // top above bottom, in image rows
  EXPECT_GT(red.bottom, red.y);
  EXPECT_GT(red.area, 20u);
  EXPECT_EQ(red.range, 0);
  const auto& green = data->blobs[1];
  EXPECT_GT(green.x, 44);  // the green disc is to the right
  EXPECT_LT(green.y, 72);  // and above
  // Every cycle is a fresh packet (1.5 kept publishing the first).
  const auto packets = camera.with([](Cmucam2Emulator& e) { return e.packets(); });
  EXPECT_TRUE(more_data(blobfinder(), 3));
  EXPECT_GE(camera.with([](Cmucam2Emulator& e) { return e.packets(); }), packets + 6);
}

TEST_F(Cmucam2DriverTest, SetColorChangesTheFirstColourTracked) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" color0 [200 240 16 60 16 60] )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  const protocol::BlobfinderColorConfig green{.subtype = protocol::kBlobfinderSetColorReq,
                                              .rmin = 16, .rmax = 60, .gmin = 180, .gmax = 240, .bmin = 16, .bmax = 60};
  EXPECT_TRUE(acked(ask(blobfinder(), green)));
  EXPECT_TRUE(camera.wait_until([](Cmucam2Emulator& e) { return e.tracked() && e.tracked()->green_min == 180; }));
  const auto data = data_when<protocol::BlobfinderData>(
      blobfinder(), [](const protocol::BlobfinderData& d) { return sees(d, 0x26d226u); });
  ASSERT_TRUE(data);
  EXPECT_GT(data->blobs[0].x, 60);  // the green disc, to the right
  auto automatic = green;
  automatic.rmin = -1;
  EXPECT_TRUE(nacked(ask(blobfinder(), automatic)));
  EXPECT_TRUE(nacked(ask(blobfinder(), std::vector<std::uint8_t>{2, 0, 0, 0, 0, 0, 0})));  // IMAGER_PARAMS
}

TEST_F(Cmucam2DriverTest, AColourOutOfViewIsNoBlob) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" color0 [100 110 100 110 240 250] )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  const auto data = next_data<protocol::BlobfinderData>(blobfinder());
  ASSERT_TRUE(data);
  EXPECT_TRUE(data->blobs.empty());
  EXPECT_EQ(data->header[0].num, 0);
}

TEST_F(Cmucam2DriverTest, BothDevicesShareOneLineAndTheServosTurnTheView) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" " + kTwoColours + ")\n"
       "ptz:0 ( driver \"cmucam2\" devicepath \"$PORT\" )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  ASSERT_TRUE(ptz().subscribe()) << devices.log.all();
  // Speed 0: the servo's own speed, straight to 10 degrees (128 + 13 positions of 0.75).
  write_command(ptz(), protocol::PtzCommand{.pan = 10, .tilt = 0, .zoom = 0, .panspeed = 0, .tiltspeed = 0});
  ASSERT_TRUE(camera.wait_until([](Cmucam2Emulator& e) { return e.servo_target(0) == 141; })) << devices.log.all();
  const auto reached = data_when<protocol::PtzData>(ptz(), [](const protocol::PtzData& d) { return d.pan == 10; });
  ASSERT_TRUE(reached);
  EXPECT_EQ(reached->pan, 10);  // 9.75 rounds to 10: within the servo's 0.75 degrees
  EXPECT_EQ(reached->zoom, 48);
  // The red disc is now in the middle of the frame.
  const auto centred = data_when<protocol::BlobfinderData>(
      blobfinder(), [](const auto& d) { return sees(d, 0xdc2626u) && d.blobs[0].x >= 43 && d.blobs[0].x <= 45; });
  ASSERT_TRUE(centred);
  EXPECT_NEAR(centred->blobs[0].x, 44, 1);
}

TEST_F(Cmucam2DriverTest, APtzSectionOfItsOwnDriverAndAGivenSpeed) {
  load("ptz:0 ( driver \"cmucam2_ptz\" port \"$PORT\" servo_resolution 0.5 )\n");
  ASSERT_TRUE(ptz().subscribe()) << devices.log.all();
  // 20 degrees at 50 deg/s: stepped there in about 0.4 s.
  write_command(ptz(), protocol::PtzCommand{.pan = -20, .tilt = 15, .zoom = 0, .panspeed = 50, .tiltspeed = 0});
  const auto moving = data_when<protocol::PtzData>(ptz(), [](const protocol::PtzData& d) { return d.pan < 0 && d.pan > -20; });
  ASSERT_TRUE(moving) << devices.log.all();
  EXPECT_EQ(moving->panspeed, 50);
  const auto there = data_when<protocol::PtzData>(
      ptz(), [](const protocol::PtzData& d) { return d.pan == -20 && d.tilt == 15 && d.panspeed == 0; });
  ASSERT_TRUE(there);
  EXPECT_EQ(there->panspeed, 0);
  EXPECT_EQ(camera.with([](Cmucam2Emulator& e) { return e.servo_target(0); }), 88);
  EXPECT_EQ(camera.with([](Cmucam2Emulator& e) { return e.servo_target(1); }), 158);
  // Velocity control: the servo moves at the signed speed until told 0.
  EXPECT_TRUE(acked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq,
                                                               .mode = protocol::kPtzVelocityControl})));
  write_command(ptz(), protocol::PtzCommand{.pan = 0, .tilt = 0, .zoom = 0, .panspeed = 40, .tiltspeed = 0});
  EXPECT_TRUE(data_when<protocol::PtzData>(ptz(), [](const protocol::PtzData& d) { return d.pan > -10; }).value_or(protocol::PtzData{}).pan > -10);
  EXPECT_TRUE(nacked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq, .mode = 7})));
  EXPECT_TRUE(nacked(ask(ptz(), std::vector<std::uint8_t>{9, 0})));
}

struct Cmucam2ReplugTest : Cmucam2DriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("cmucam2-replug");
    return {.tcp = false, .symlink = scratch.file("ttyCMUCAM"), .faults = {}};
  }
  Cmucam2ReplugTest() : Cmucam2DriverTest({}, on_a_symlink()) {}
};

TEST_F(Cmucam2ReplugTest, ACameraUnpluggedIsFoundAgain) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" color0 [200 240 16 60 16 60] )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  ASSERT_TRUE(next_data<protocol::BlobfinderData>(blobfinder()));
  camera.replug();
  EXPECT_FALSE(devices.log.first_with({"lost"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"is back after"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(blobfinder(), 2)) << devices.log.all();
  EXPECT_TRUE(camera.with([](Cmucam2Emulator& e) { return e.poll_mode(); }));  // started anew
}

TEST_F(Cmucam2DriverTest, RefusesTheSubscriptionWhenNothingAnswers) {
  camera.replug(false);
  devices.load("blobfinder:0 ( driver \"cmucam2\" port \"" + camera.port() + "\" )\n");
  EXPECT_FALSE(blobfinder().subscribe());
}

// The kit's faults: each loses a reply at most, which is asked for again.
struct Fault {
  double emulators::FaultPlan::*kind;
  double rate;
};

emulators::FaultPlan plan_of(Fault fault) {
  emulators::FaultPlan plan;
  plan.*fault.kind = fault.rate;
  return plan;
}

struct Cmucam2FaultTest : Cmucam2DriverTest, ::testing::WithParamInterface<Fault> {
  Cmucam2FaultTest() : Cmucam2DriverTest({}, {.tcp = false, .symlink = {}, .faults = plan_of(GetParam())}) {}
};

TEST_P(Cmucam2FaultTest, ABadLineLosesNothingButTime) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" " + kTwoColours + ")\n"
       "ptz:0 ( driver \"cmucam2\" devicepath \"$PORT\" )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  ASSERT_TRUE(ptz().subscribe()) << devices.log.all();
  write_command(ptz(), protocol::PtzCommand{.pan = 10, .tilt = 0, .zoom = 0, .panspeed = 0, .tiltspeed = 0});
  EXPECT_TRUE(data_when<protocol::PtzData>(ptz(), [](const protocol::PtzData& d) { return d.pan == 10; }, 10s));
  const auto centred = data_when<protocol::BlobfinderData>(
      blobfinder(), [](const auto& d) { return d.blobs.size() == 2 && d.blobs[0].x >= 43 && d.blobs[0].x <= 45; }, 10s);
  ASSERT_TRUE(centred) << devices.log.all();
  EXPECT_TRUE(more_data(blobfinder(), 5, 10s));
  // Three bad replies in a row may still lose the camera for a moment: it is found again at once.
  const auto losses = devices.log.count("lost the robot", core::LogLevel::kWarning);
  EXPECT_LE(losses, 1u) << devices.log.all();
  if (losses > 0) {
    EXPECT_FALSE(devices.log.first_with({"is back after"}, 5s).empty()) << devices.log.all();
  }
}

INSTANTIATE_TEST_SUITE_P(EachFault, Cmucam2FaultTest,
                         // Drops are per byte: 1 % loses about a third of the T packets.
                         ::testing::Values(Fault{&emulators::FaultPlan::bad_checksum, 0.2},
                                           Fault{&emulators::FaultPlan::garbage, 0.2},
                                           Fault{&emulators::FaultPlan::truncate, 0.05},
                                           Fault{&emulators::FaultPlan::drop, 0.01}));

struct Cmucam2SlowBootTest : Cmucam2DriverTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan made;
    made.silent_start = 1s;
    return made;
  }
  Cmucam2SlowBootTest() : Cmucam2DriverTest({}, {.tcp = false, .symlink = {}, .faults = plan()}) {}
};

// A camera still booting when the first device subscribes is waited for.
TEST_F(Cmucam2SlowBootTest, ACameraSilentAtFirstIsWaitedFor) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" color0 [200 240 16 60 16 60] )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  EXPECT_TRUE(next_data<protocol::BlobfinderData>(blobfinder()));
}

struct Cmucam2SilentStartTest : Cmucam2DriverTest {
  static emulators::FaultPlan plan() {
    emulators::FaultPlan made;
    made.vanish_at = 1s;
    made.vanish_for = 2s;
    return made;
  }
  Cmucam2SilentStartTest() : Cmucam2DriverTest({}, {.tcp = false, .symlink = {}, .faults = plan()}) {}
};

// The line goes dead both ways for a while: the camera's silence loses it,
// and it is started again when it answers.
TEST_F(Cmucam2SilentStartTest, ACameraThatFallsSilentIsLostAndFoundAgain) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" color0 [200 240 16 60 16 60] )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"lost the robot", "no reply"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"is back after"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(blobfinder(), 2)) << devices.log.all();
  EXPECT_EQ(counter(blobfinder().driver(), "reconnects"), 1u);
}

struct Cmucam2FreshDataTest : Cmucam2DriverTest {
  Cmucam2FreshDataTest() : Cmucam2DriverTest({.prompt_after_packet = false}) {}
};

TEST_F(Cmucam2FreshDataTest, ReadsPacketsWithoutAPromptAfterThemToo) {
  load("blobfinder:0 ( driver \"cmucam2\" devicepath \"$PORT\" color0 [200 240 16 60 16 60] )\n");
  ASSERT_TRUE(blobfinder().subscribe()) << devices.log.all();
  const auto data = data_when<protocol::BlobfinderData>(blobfinder(), [](const auto& d) { return d.blobs.size() == 1; });
  ASSERT_TRUE(data);
  EXPECT_NEAR(data->blobs[0].x, 26, 1);
  EXPECT_TRUE(more_data(blobfinder(), 3));
}

TEST(Cmucam2Options, BadValuesAreRefusedAtTheirPlace) {
  const std::string bound = config_error_of("blobfinder:0 ( driver \"cmucam2\" devicepath \"/tmp/c\" color0 [200 300 16 60 16 60] )\n");
  EXPECT_NE(bound.find(":1:65: cmucam2: color0 bounds must be whole numbers from 0 to 255"), std::string::npos) << bound;
  const std::string order = config_error_of("blobfinder:0 ( driver \"cmucam2\" devicepath \"/tmp/c\" color0 [240 200 16 60 16 60] )\n");
  EXPECT_NE(order.find("cmucam2: color0 each minimum must not exceed its maximum"), std::string::npos) << order;
  const std::string many = config_error_of("blobfinder:0 ( driver \"cmucam2\" devicepath \"/tmp/c\" num_blobs 11 )\n");
  EXPECT_NE(many.find("cmucam2: num_blobs"), std::string::npos) << many;
}

}  // namespace cmucam2_driver_test
}  // namespace playerkit::drivers::testing
