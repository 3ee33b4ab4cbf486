// The emulated CMUcam2 on a simulated clock: every reply of cmucam2.md §6,
// tracking in the synthetic scene and in an image, the servos.

#include "families/cmucam2/emulator/cmucam2_emulator.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/scratch_directory.hpp"

namespace playerkit::emulators {
namespace cmucam2_emulator_test {

using testing::ScratchDirectory;

using namespace std::chrono_literals;
namespace cam = hardware::cmucam2;

const cam::ColorBounds kRed{200, 240, 16, 60, 16, 60};
const cam::ColorBounds kGreen{16, 60, 180, 240, 16, 60};

struct Camera {
  explicit Camera(Cmucam2EmulatorOptions options = {}, cmucam2::Scene scene = Cmucam2Emulator::default_scene())
      : emulator(std::move(scene), options) {}

  // What the camera says to `text` (sent with its CR) within `wait`.
  std::string say(const std::string& text, Duration wait = 0ms) {
    const auto bytes = cam::encode(text);
    emulator.receive(bytes, now, 115200);
    return pass(wait);
  }
  std::string pass(Duration wait) {
    now += wait;
    emulator.advance(now);
    std::string out;
    for (const Telegram& telegram : emulator.take_output()) out.append(telegram.bytes.begin(), telegram.bytes.end());
    return out;
  }
  cam::TPacket packet_of(const cam::ColorBounds& bounds) {
    const std::string reply = say(cam::track_color(bounds), 40ms);
    EXPECT_EQ(reply.substr(0, 4), "ACK\r") << reply;
    const auto packet = cam::parse_t_packet(reply.substr(4, reply.find('\r', 4) - 4));
    EXPECT_TRUE(packet) << reply;
    return packet.value_or(cam::TPacket{});
  }

  Cmucam2Emulator emulator;
  Duration now{0};
};

TEST(Cmucam2Emulator, SaysNothingUntilSpokenToThenAnswersAsTheSheetSays) {
  Camera camera;
  EXPECT_EQ(camera.pass(1s), "");
  EXPECT_EQ(camera.say("PM 1"), "ACK\r:");  // exactly 5 bytes (§6.3)
  EXPECT_TRUE(camera.emulator.poll_mode());
  EXPECT_EQ(camera.say("PM 0"), "ACK\r:");
  EXPECT_EQ(camera.say(""), "ACK\r:");  // a lone CR (§6.5)
  EXPECT_EQ(camera.say("XY 3"), "NCK\r:");  // unknown (§6.7)
  EXPECT_EQ(camera.say("PM 2"), "NCK\r:");
  EXPECT_EQ(camera.say("GV"), "ACK\rCMUcam2 v1.00 c6\r:");
  EXPECT_EQ(camera.say("CP 1"), "ACK\r:");
  EXPECT_EQ(camera.emulator.refused(), 2u);
  // A TC is never refused (§6.4): a bound beyond a byte is taken at its end.
  EXPECT_EQ(camera.say("TC 200 300 16 60 16 60"), "ACK\r");
  EXPECT_EQ(camera.emulator.tracked(), (cam::ColorBounds{200, 255, 16, 60, 16, 60}));
}

TEST(Cmucam2Emulator, InPollModeAnswersTcWithAckThenOnePacketAFrameLaterAndThePrompt) {
  Camera camera;
  camera.say("PM 1");
  // 1.5's command, with its space before the CR (§1.1).
  EXPECT_EQ(camera.say("TC 200 240 16 60 16 60 "), "ACK\r");
  EXPECT_EQ(camera.pass(10ms), "");  // paced at the frame time (§6.8)
  const std::string packet = camera.pass(25ms);
  ASSERT_EQ(packet.back(), ':') << packet;
  const auto parsed = cam::parse_t_packet(packet.substr(0, packet.size() - 1));
  ASSERT_TRUE(parsed) << packet;
  // The red disc, 10 degrees to the left: 44 - 10 / (48 / 88) columns, mid-height.
  EXPECT_NEAR(parsed->mx, 26, 1);
  EXPECT_NEAR(parsed->my, 72, 1);
  EXPECT_LT(parsed->x1, parsed->mx);
  EXPECT_GT(parsed->x2, parsed->mx);
  EXPECT_GT(parsed->pixels, 20);
  EXPECT_GT(parsed->confidence, 150);  // a disc fills about pi/4 of its box
  EXPECT_EQ(camera.pass(1s), "");      // one packet only
  EXPECT_EQ(camera.say(""), "ACK\r:");
}

TEST(Cmucam2Emulator, DataFreshModeLeavesThePromptToTheCr) {
  Camera camera({.prompt_after_packet = false});
  camera.say("PM 1");
  const std::string reply = camera.say("TC 200 240 16 60 16 60", 40ms);
  EXPECT_EQ(reply.back(), '\r') << reply;
  EXPECT_EQ(camera.say(""), "ACK\r:");
}

TEST(Cmucam2Emulator, StreamsAPacketEveryFrameUntilTheNextCommand) {
  Camera camera;
  EXPECT_EQ(camera.say(cam::track_color(kGreen)), "ACK\r");
  EXPECT_TRUE(camera.emulator.streaming());
  const std::string stream = camera.pass(100ms);
  EXPECT_EQ(std::count(stream.begin(), stream.end(), 'T'), 3) << stream;
  EXPECT_EQ(stream.find(':'), std::string::npos);
  EXPECT_EQ(camera.say(""), "ACK\r:");
  EXPECT_FALSE(camera.emulator.streaming());
  EXPECT_EQ(camera.pass(1s), "");
  // TC alone tracks the last colour again.
  EXPECT_EQ(camera.say("TC"), "ACK\r");
  EXPECT_EQ(camera.emulator.tracked(), kGreen);
}

TEST(Cmucam2Emulator, AColourNotInViewGivesAnAllZeroPacket) {
  Camera camera;
  camera.say("PM 1");
  EXPECT_EQ(camera.packet_of({100, 110, 100, 110, 240, 250}), cam::TPacket{});
}

TEST(Cmucam2Emulator, ServosSlewToTheirPositionsAndTurnTheView) {
  Camera camera;
  camera.say("PM 1");
  EXPECT_EQ(camera.say("GS 0"), "ACK\r128\r:");
  // 10 degrees left: 128 + 10 / 0.75 = 141.
  EXPECT_EQ(camera.say("SV 0 141"), "ACK\r:");
  EXPECT_EQ(camera.say("GS 0"), "ACK\r141\r:");  // what was commanded, at once
  EXPECT_LT(camera.emulator.servo_position(0), 141);
  camera.pass(20ms);
  EXPECT_NEAR(camera.emulator.servo_position(0), 136, 0.01);  // 400 positions/s
  camera.pass(1s);
  EXPECT_DOUBLE_EQ(camera.emulator.pan_degrees(), 9.75);
  const cam::TPacket centred = camera.packet_of(kRed);
  EXPECT_NEAR(centred.mx, 44, 1);
  EXPECT_EQ(camera.say("SV 5 100"), "NCK\r:");
  EXPECT_EQ(camera.say("SV 1 256"), "NCK\r:");
  EXPECT_EQ(camera.say("RS"), "ACK\rCMUcam2 v1.00 c6\r:");
  EXPECT_EQ(camera.emulator.servo_target(0), 128);
}

// Found by running Player 2.1.3's cmucam2 against the emulator (docs/reference-checks/2026-12-08-serial-sensors.md):
// its Setup sends `SM 0` (servo mask: auto-servoing off), which a CMUcam2 acknowledges; an NCK made it print
// "Disabling auto-servo failed". The mask is accepted (0..15); the servos stay where SV puts them.
TEST(Cmucam2Emulator, AcceptsTheServoMask) {
  Camera camera;
  EXPECT_EQ(camera.say("SM 0"), "ACK\r:");
  EXPECT_EQ(camera.say("SM 15"), "ACK\r:");
  EXPECT_EQ(camera.say("SM 16"), "NCK\r:");
  EXPECT_EQ(camera.say("SM"), "NCK\r:");
  EXPECT_EQ(camera.say("GS 0"), "ACK\r128\r:");
}

TEST(Cmucam2Emulator, TracksColourInAnImage) {
  ScratchDirectory dir("cmucam2-image");
  const auto file = dir.path() / "scene.ppm";
  {
    // 88 x 143, dark, with a blue square at columns 60-69, rows 20-29.
    std::ofstream out(file, std::ios::binary);
    out << "P6\n# a test scene\n88 143\n255\n";
    for (int y = 0; y < 143; ++y) {
      for (int x = 0; x < 88; ++x) {
        const bool blue = x >= 60 && x < 70 && y >= 20 && y < 30;
        out << static_cast<char>(blue ? 20 : 10) << static_cast<char>(blue ? 20 : 10)
            << static_cast<char>(blue ? 220 : 10);
      }
    }
  }
  Camera camera({}, cmucam2::Scene(cmucam2::read_ppm(file)));
  camera.say("PM 1");
  const cam::TPacket packet = camera.packet_of({0, 40, 0, 40, 200, 240});
  EXPECT_EQ(packet, (cam::TPacket{65, 25, 61, 21, 70, 30, 13, 255}));
  EXPECT_THROW((void)cmucam2::read_ppm(dir.path() / "missing.ppm"), std::invalid_argument);
}

}  // namespace cmucam2_emulator_test
}  // namespace playerkit::emulators
