// The sonyevid30 driver against the emulated EVI-D30 on a real
// pseudo-terminal, through the kit's driver harness: start-up, the ptz
// mapping both ways, movement mode, raw VISCA through GENERIC_CONFIG, a full
// command buffer, the options, and each of the kit's faults.

#include "families/sonyevid30/driver/sonyevid30_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/sonyevid30/driver/sonyevid30_options.hpp"
#include "families/sonyevid30/emulator/evid30_emulator.hpp"
#include "families/sonyevid30/protocol/evid30_units.hpp"
#include "families/sonyevid30/protocol/visca.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::drivers::testing {
namespace {

using emulators::Evid30Emulator;
namespace visca = hardware::sonyevid30;

struct Sonyevid30DriverTest : ::testing::Test {
  explicit Sonyevid30DriverTest(LineOptions options = {})
      : camera([] { return std::make_unique<Evid30Emulator>(); }, std::move(options)) {}

  core::Device& ptz() { return devices.device(protocol::kPtzCode); }
  void start(const std::string& extra = "", const std::string& before = "") {
    devices.load(before + "ptz:0 ( driver \"sonyevid30\" port \"$PORT\" " + extra + ")\n", camera.port());
    ASSERT_TRUE(ptz().subscribe()) << devices.log.all();
  }
  std::optional<protocol::PtzData> reaches(std::int16_t pan, std::int16_t tilt, std::chrono::milliseconds limit = 10s) {
    return data_when<protocol::PtzData>(ptz(), [&](const auto& d) { return d.pan == pan && d.tilt == tilt; }, limit);
  }
  std::optional<core::Reply> generic(std::initializer_list<std::uint8_t> message) {
    protocol::PtzGenericConfig request;
    request.subtype = protocol::kPtzGenericConfigReq;
    request.length = static_cast<std::uint16_t>(message.size());
    std::copy(message.begin(), message.end(), request.config.begin());
    return ask(ptz(), request);
  }
  static std::string config_hex(const std::optional<core::Reply>& reply) {
    const auto answer = protocol::decode<protocol::PtzGenericConfig>(reply->payload);
    return visca::hex(std::span(answer.config.data(), answer.length));
  }

  EmulatedLine<Evid30Emulator> camera;
  ConfiguredDevices devices;
};

TEST_F(Sonyevid30DriverTest, StartsWithoutMovingTheCameraAndPublishesWhereItPoints) {
  start();
  const auto data = next_data<protocol::PtzData>(ptz());
  ASSERT_TRUE(data);
  EXPECT_EQ(data->pan, 0);
  EXPECT_EQ(data->tilt, 0);
  EXPECT_EQ(data->zoom, 30);  // zoom 0: the widest field of view
  EXPECT_EQ(data->panspeed, 0);
  EXPECT_EQ(camera.with([](Evid30Emulator& e) { return e.commands(); }), 0u);
}

TEST_F(Sonyevid30DriverTest, PointsTheCameraWhereTheClientSaysAndReadsBackEveryDegree) {
  start();
  // The sheet's worked examples: pan +30 -> -264 units, tilt +10 -> 120, fov 20 -> 0x17B.
  write_command(ptz(), protocol::PtzCommand{.pan = 30, .tilt = 10, .zoom = 20, .panspeed = 0, .tiltspeed = 0});
  EXPECT_TRUE(camera.wait_until([](Evid30Emulator& e) {
    return e.pan_units() == -264 && e.tilt_units() == 120 && e.zoom_units() == 0x17B;
  })) << devices.log.all();
  // 1.5 read back 29 and 21.
  EXPECT_TRUE(data_when<protocol::PtzData>(ptz(), [](const auto& d) {
    return d.pan == 30 && d.tilt == 10 && d.zoom == 20;
  })) << devices.log.all();
  write_command(ptz(), protocol::PtzCommand{.pan = -7, .tilt = -3, .zoom = 20, .panspeed = 0, .tiltspeed = 0});
  EXPECT_TRUE(reaches(-7, -3));
  EXPECT_EQ(devices.log.count("refused"), 0u) << devices.log.all();
}

TEST_F(Sonyevid30DriverTest, ClampsDemandsToTheCamerasRange) {
  start();
  write_command(ptz(), protocol::PtzCommand{.pan = 170, .tilt = -80, .zoom = 1, .panspeed = 0, .tiltspeed = 0});
  EXPECT_TRUE(camera.wait_until([](Evid30Emulator& e) {
    return e.pan_units() == visca::kPanMinUnits && e.tilt_units() == visca::kTiltMinUnits &&
           e.zoom_units() == visca::kZoomMaxUnits;
  }, 10s));
  // Full tele reads 3.03 degrees.
  EXPECT_TRUE(data_when<protocol::PtzData>(ptz(), [](const auto& d) {
    return d.pan == 100 && d.tilt == -25 && d.zoom == 3;
  }));
}

TEST_F(Sonyevid30DriverTest, MovementModeDrivesTowardTheDemandAndStopsThere) {
  start("movement 1");
  write_command(ptz(), protocol::PtzCommand{.pan = -40, .tilt = 15, .zoom = 30, .panspeed = 0, .tiltspeed = 0});
  ASSERT_TRUE(reaches(-40, 15)) << devices.log.all();
  // Stopped within half a degree (and the little a 100 ms cycle at the slowest speed adds): it stays there.
  ASSERT_TRUE(more_data(ptz(), 3));
  const double pan = camera.with([](Evid30Emulator& e) { return e.pan_units(); });
  EXPECT_NEAR(visca::pan_degrees(static_cast<int>(std::lround(pan))), -40, 0.8);
  EXPECT_TRUE(more_data(ptz(), 5));
  EXPECT_EQ(camera.with([](Evid30Emulator& e) { return e.pan_units(); }), pan);
}

TEST_F(Sonyevid30DriverTest, PassesRawViscaThroughGenericConfig) {
  start();
  // An inquiry: its answer packet; a command: its ACK packet.
  const auto zoom = generic({0x09, 0x04, 0x47});
  ASSERT_TRUE(acked(zoom));
  EXPECT_EQ(config_hex(zoom), "90 50 00 00 00 00 FF");
  const auto power_on = generic({0x01, 0x04, 0x00, 0x02});
  ASSERT_TRUE(acked(power_on));
  EXPECT_EQ(config_hex(power_on), "90 41 FF");
  // A message the camera calls a syntax error: NACK and one clear line (1.5 hung).
  EXPECT_TRUE(nacked(generic({0x01, 0x06, 0x02, 0x19, 0x14, 0, 0, 0, 0, 0, 0, 0, 0})));
  EXPECT_FALSE(devices.log.first_with({"GENERIC_CONFIG", "refused", "syntax error"}).empty()) << devices.log.all();
  // Too long for VISCA, empty, neither command nor inquiry.
  EXPECT_TRUE(nacked(generic({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15})));
  EXPECT_TRUE(nacked(generic({})));
  EXPECT_TRUE(nacked(generic({0x21})));
  EXPECT_TRUE(more_data(ptz(), 2));  // the driver goes on
}

TEST_F(Sonyevid30DriverTest, AnswersControlModeAndUnknownRequests) {
  start();
  EXPECT_TRUE(acked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq,
                                                               .mode = protocol::kPtzPositionControl})));
  EXPECT_TRUE(nacked(ask(ptz(), protocol::PtzVelocityModeConfig{.subtype = protocol::kPtzControlModeReq,
                                                                .mode = protocol::kPtzVelocityControl})));
  EXPECT_TRUE(nacked(ask(ptz(), std::vector<std::uint8_t>{9, 0})));  // 1.5 left both unanswered
}

// Both sockets busy (a long pan and a long zoom) and a third command: the
// camera says its buffer is full; the driver cancels one and sends again.
TEST_F(Sonyevid30DriverTest, AFullCommandBufferIsClearedByCancellingOneSocket) {
  start();
  write_command(ptz(), protocol::PtzCommand{.pan = -100, .tilt = 0, .zoom = 3, .panspeed = 0, .tiltspeed = 0});
  ASSERT_TRUE(camera.wait_until([](Evid30Emulator& e) { return e.busy_sockets() == 2; })) << devices.log.all();
  EXPECT_TRUE(acked(generic({0x01, 0x04, 0x00, 0x02})));
  EXPECT_EQ(camera.with([](Evid30Emulator& e) { return e.cancels(); }), 1u);
  EXPECT_EQ(counter(ptz().driver(), "cancelled_commands"), 1u);
}

// A camera that errs where the emulator never does (sheet §6.6): every
// command refused instead of ACKed, or every completion replaced by "not
// executable" after its ACK.
class ErringCamera final : public emulators::DeviceEmulator {
 public:
  enum class Fault { refuse_commands, fail_after_ack };
  explicit ErringCamera(Fault fault) : fault_(fault) {}
  void receive(std::span<const std::uint8_t> bytes, emulators::Duration now, int baud) override {
    camera_.receive(bytes, now, baud);
  }
  void advance(emulators::Duration now) override { camera_.advance(now); }
  [[nodiscard]] emulators::Duration next_deadline() const override { return camera_.next_deadline(); }
  [[nodiscard]] std::string describe() const override { return "an erring " + camera_.describe(); }
  std::vector<emulators::Telegram> take_output() override {
    std::vector<emulators::Telegram> out;
    for (emulators::Telegram& telegram : camera_.take_output()) {
      const visca::Reply reply = visca::parse_reply(telegram.bytes);
      if (fault_ == Fault::refuse_commands && reply.kind == visca::Reply::Kind::completion) continue;
      if ((fault_ == Fault::refuse_commands && reply.kind == visca::Reply::Kind::ack) ||
          (fault_ == Fault::fail_after_ack && reply.kind == visca::Reply::Kind::completion)) {
        telegram.bytes = visca::error_reply(reply.socket, visca::kNotExecutable);
      }
      out.push_back(std::move(telegram));
    }
    return out;
  }

 private:
  Fault fault_;
  Evid30Emulator camera_;
};

struct Sonyevid30ErrorTest : ::testing::TestWithParam<ErringCamera::Fault> {
  Sonyevid30ErrorTest() : camera([] { return std::make_unique<ErringCamera>(GetParam()); }) {}
  core::Device& ptz() { return devices.device(protocol::kPtzCode); }
  EmulatedLine<ErringCamera> camera;
  ConfiguredDevices devices;
};

// Errors are reported in one clear line each, and the driver goes on (1.5 printed and waited forever).
TEST_P(Sonyevid30ErrorTest, ErrorPacketsAreReportedAndTheDriverGoesOn) {
  devices.load("ptz:0 ( driver \"sonyevid30\" port \"$PORT\" )\n", camera.port());
  ASSERT_TRUE(ptz().subscribe()) << devices.log.all();
  write_command(ptz(), protocol::PtzCommand{.pan = 5, .tilt = 0, .zoom = 30, .panspeed = 0, .tiltspeed = 0});
  if (GetParam() == ErringCamera::Fault::refuse_commands) {
    EXPECT_FALSE(devices.log.first_with({"refused absolute pan/tilt (81 01 06 02 18 14 0F 0F 0D 04 00 00 00 00 FF)",
                                         "command not executable"}).empty())
        << devices.log.all();
    EXPECT_FALSE(devices.log.first_with({"refused zoom direct (81 01 04 47 00 00 00 00 FF)"}).empty());
    EXPECT_EQ(counter(ptz().driver(), "refused_commands"), 2u);
  } else {
    // The zoom (already there) fails at once in socket 2, the pan when its motion ends in socket 1.
    EXPECT_FALSE(devices.log.first_with({"could not finish the command in socket 2", "not executable"}).empty())
        << devices.log.all();
    EXPECT_FALSE(devices.log.first_with({"could not finish the command in socket 1", "not executable"}).empty())
        << devices.log.all();
    EXPECT_TRUE(eventually([&] { return counter(ptz().driver(), "late_errors") == 2; }));
  }
  EXPECT_TRUE(more_data(ptz(), 3)) << devices.log.all();
  EXPECT_EQ(devices.log.count("lost the EVI-D30"), 0u) << devices.log.all();
}

INSTANTIATE_TEST_SUITE_P(Faults, Sonyevid30ErrorTest,
                         ::testing::Values(ErringCamera::Fault::refuse_commands, ErringCamera::Fault::fail_after_ack));

TEST(Sonyevid30Options, BadValuesAreRefusedAtTheirPlace) {
  const std::string reversed = "ptz:0 ( driver \"sonyevid30\" port \"/tmp/cam\" fov [30 3] )\n";
  EXPECT_NE(config_error_of(reversed).find(":1:50: sonyevid30: fov must be"), std::string::npos) << config_error_of(reversed);
  const std::string negative = "ptz:0 ( driver \"sonyevid30\" port \"/tmp/cam\" movement -1 )\n";
  EXPECT_NE(config_error_of(negative).find("sonyevid30: movement"), std::string::npos) << config_error_of(negative);
  EXPECT_EQ(config_error_of("ptz:0 ( driver \"sonyevid30\" port \"/tmp/cam\" fov [3 30] movement 1 )\n"), "no error");
}

// The README's options table is the schema's own (between "<!-- options -->" and "<!-- end options -->").
TEST(Sonyevid30Options, TheReadmeTableIsGeneratedFromTheSchema) {
  EXPECT_EQ(readme_options_table(std::string(PLAYERKIT_TEST_DATA_DIR) + "/../../lib/families/sonyevid30/README.md", ""),
            sonyevid30::sonyevid30_option_schema().markdown());
}

// 1.5's own form, in a radians file: the numbers are degrees all the same.
TEST_F(Sonyevid30DriverTest, TheFieldOfViewIsInDegreesWhateverTheAngleUnit) {
  start("fov [5 50]", "unit_angle \"radians\"\n");
  write_command(ptz(), protocol::PtzCommand{.pan = 0, .tilt = 0, .zoom = 20, .panspeed = 0, .tiltspeed = 0});
  // 1024 * (20 - 50) / (5 - 50) = 682.7
  EXPECT_TRUE(camera.wait_until([](Evid30Emulator& e) { return e.zoom_units() == 683; })) << devices.log.all();
  EXPECT_TRUE(data_when<protocol::PtzData>(ptz(), [](const auto& d) { return d.zoom == 20; }));
}

TEST_F(Sonyevid30DriverTest, RefusesTheSubscriptionWhenNothingAnswers) {
  camera.replug(false);
  devices.load("ptz:0 ( driver \"sonyevid30\" port \"" + camera.port() + "\" )\n");
  EXPECT_FALSE(ptz().subscribe());
}

struct Sonyevid30ReplugTest : Sonyevid30DriverTest {
  static LineOptions on_a_symlink() {
    static ::playerkit::testing::ScratchDirectory scratch("sonyevid30-replug");
    return {.tcp = false, .symlink = scratch.file("ttyCAM"), .faults = {}};
  }
  Sonyevid30ReplugTest() : Sonyevid30DriverTest(on_a_symlink()) {}
};

TEST_F(Sonyevid30ReplugTest, ACameraUnpluggedAndBackIsFoundAgain) {
  start();
  ASSERT_TRUE(next_data<protocol::PtzData>(ptz()));
  camera.replug();
  EXPECT_FALSE(devices.log.first_with({"lost the EVI-D30"}).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  write_command(ptz(), protocol::PtzCommand{.pan = 12, .tilt = -4, .zoom = 30, .panspeed = 0, .tiltspeed = 0});
  EXPECT_TRUE(reaches(12, -4)) << devices.log.all();
}

struct Sonyevid30FaultTest : Sonyevid30DriverTest {
  explicit Sonyevid30FaultTest(emulators::FaultPlan plan)
      : Sonyevid30DriverTest({.tcp = false, .symlink = {}, .faults = plan}) {}
  static emulators::FaultPlan plan(const std::string& fault) {
    emulators::FaultPlan faults;
    emulators::add_fault(faults, fault);
    return faults;
  }
  emulators::InjectedFaults injected() { return camera.runner().stats().faults; }
};

struct Sonyevid30SilentSpellTest : Sonyevid30FaultTest {
  Sonyevid30SilentSpellTest() : Sonyevid30FaultTest(plan("vanish=1:2")) {}
};

// The line goes dead both ways for a while: the camera is lost, and found
// again when it answers.
TEST_F(Sonyevid30SilentSpellTest, ACameraThatFallsSilentIsLostAndFoundAgain) {
  start();
  EXPECT_FALSE(devices.log.first_with({"lost the EVI-D30", "no reply"}, 10s).empty()) << devices.log.all();
  EXPECT_FALSE(devices.log.first_with({"answers again"}, 10s).empty()) << devices.log.all();
  EXPECT_TRUE(more_data(ptz(), 2)) << devices.log.all();
  EXPECT_EQ(counter(ptz().driver(), "reconnects"), 1u);
}

struct Sonyevid30SlowWakeTest : Sonyevid30FaultTest {
  Sonyevid30SlowWakeTest() : Sonyevid30FaultTest(plan("silent-start=0.4")) {}
};

// A camera silent for its first 0.4 s: the start-up inquiry is asked again.
TEST_F(Sonyevid30SlowWakeTest, ACameraSlowToAnswerIsWaitedFor) {
  start();
  EXPECT_TRUE(next_data<protocol::PtzData>(ptz())) << devices.log.all();
  EXPECT_GT(counter(ptz().driver(), "retries"), 0u);
}

// Noise, damaged terminators, packets cut short, bytes lost: replies are
// found behind the damage or asked for again, and the camera gets there.
struct Sonyevid30DeafCameraTest : Sonyevid30FaultTest {
  Sonyevid30DeafCameraTest() : Sonyevid30FaultTest(plan("silent-start=60")) {}
};

TEST_F(Sonyevid30DeafCameraTest, ASilentLineRefusesTheSubscriptionSayingWhatWasAsked) {
  devices.load("ptz:0 ( driver \"sonyevid30\" port \"" + camera.port() + "\" )\n");
  EXPECT_FALSE(ptz().subscribe());
  EXPECT_FALSE(devices.log.first_with({"pan/tilt position inquiry", "VISCA camera"}).empty()) << devices.log.all();
}

struct Sonyevid30NoisyLineTest : Sonyevid30FaultTest, ::testing::WithParamInterface<const char*> {
  Sonyevid30NoisyLineTest() : Sonyevid30FaultTest(plan(GetParam())) {}
};

TEST_P(Sonyevid30NoisyLineTest, TheCameraIsPointedAllTheSame) {
  start();
  write_command(ptz(), protocol::PtzCommand{.pan = -45, .tilt = 20, .zoom = 10, .panspeed = 0, .tiltspeed = 0});
  ASSERT_TRUE(reaches(-45, 20, 15s)) << devices.log.all();
  EXPECT_TRUE(eventually([this] {
    const emulators::InjectedFaults faults = injected();
    return faults.garbage_runs + faults.bad_checksums + faults.truncated + faults.dropped_bytes >= 5;
  }, 15s));
  write_command(ptz(), protocol::PtzCommand{.pan = 60, .tilt = -20, .zoom = 25, .panspeed = 0, .tiltspeed = 0});
  EXPECT_TRUE(reaches(60, -20, 15s)) << devices.log.all();
}

INSTANTIATE_TEST_SUITE_P(Faults, Sonyevid30NoisyLineTest,
                         ::testing::Values("garbage=0.3", "bad-checksum=0.1", "truncate=0.1", "drop=0.02"));

}  // namespace
}  // namespace playerkit::drivers::testing
