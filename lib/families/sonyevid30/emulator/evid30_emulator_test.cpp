// The emulated EVI-D30 on a simulated clock, against sonyevid30.md §6: what
// it answers, when it completes, how it moves, sockets and cancels.

#include "families/sonyevid30/emulator/evid30_emulator.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "families/sonyevid30/protocol/evid30_units.hpp"
#include "families/sonyevid30/protocol/visca.hpp"

namespace playerkit::emulators {
namespace {

using namespace std::chrono_literals;
namespace visca = hardware::sonyevid30;

// A host on a simulated clock; what the camera sent, as hex, telegrams joined by " | ".
struct Host {
  Evid30Emulator camera;
  Duration now{0};

  std::string send(const visca::Bytes& bytes) {
    camera.receive(bytes, now, 9600);
    return replies();
  }
  std::string replies() {
    std::string out;
    for (const Telegram& telegram : camera.take_output()) out += (out.empty() ? "" : " | ") + visca::hex(telegram.bytes);
    return out;
  }
  void wait(Duration duration) {
    const Duration until = now + duration;
    while (camera.next_deadline() <= until) {
      now = camera.next_deadline();
      camera.advance(now);
    }
    now = until;
    camera.advance(now);
  }
};

TEST(Evid30Emulator, AnswersInquiriesAtOnceWithNibbles) {
  Host host;
  EXPECT_EQ(host.send(visca::pan_tilt_inquiry()), "90 50 00 00 00 00 00 00 00 00 FF");
  EXPECT_EQ(host.send(visca::zoom_inquiry()), "90 50 00 00 00 00 FF");
  // An inquiry it does not model still gets an answer (a 1.5 driver would wait forever).
  EXPECT_EQ(host.send({0x81, 0x09, 0x04, 0x4B, 0xFF}), "90 50 00 FF");
  // Broadcasts are tolerated; nothing is sent unasked.
  EXPECT_EQ(host.send({0x88, 0x30, 0x01, 0xFF}), "88 30 02 FF");
  EXPECT_EQ(host.send({0x88, 0x01, 0x00, 0x01, 0xFF}), "88 01 00 01 FF");
  host.wait(5s);
  EXPECT_EQ(host.replies(), "");
}

// Found by running Player 2.1.3's sonyevid30 against the emulator (docs/reference-checks/2026-12-08-serial-sensors.md):
// it asks for the camera type and the power state at start-up, as a real EVI-D30 answers them. An answer of
// `90 50 00 FF` to either made it report "Unknown camera type: 0" and "Failed to communicate with camera".
TEST(Evid30Emulator, AnswersPowerAndDeviceTypeInquiriesAsAnEviD30) {
  Host host;
  EXPECT_EQ(host.send({0x81, 0x09, 0x04, 0x00, 0xFF}), "90 50 02 FF");  // CAM_PowerInq: on
  // Device type: vendor 0020 (Sony), model 0402 (EVI-D30/D31), ROM version, 2 sockets; within the 11 bytes a
  // 1.5 driver reads.
  const std::string type = host.send({0x81, 0x09, 0x00, 0x02, 0xFF});
  EXPECT_EQ(type.substr(0, 18), "90 50 00 20 04 02 ");
  EXPECT_EQ(type.substr(type.size() - 5), "02 FF");
  EXPECT_EQ(type.size(), std::string("90 50 00 20 04 02 01 18 02 FF").size());
  // Longer or other inquiries of the same family are not these two.
  EXPECT_EQ(host.send({0x81, 0x09, 0x00, 0x02, 0x00, 0xFF}), "90 50 00 FF");
}

TEST(Evid30Emulator, MovesToAnAbsoluteTargetAndCompletesItsSocketThere) {
  Host host;
  // Player pan +30, tilt +10 (the sheet's worked example).
  EXPECT_EQ(host.send(visca::absolute_pan_tilt(-264, 120)), "90 41 FF");
  EXPECT_EQ(host.camera.busy_sockets(), 1);
  host.wait(100ms);  // 80 deg/s: 8 degrees of 30
  EXPECT_NEAR(host.camera.pan_units(), -8 * 8.8, 0.5);
  EXPECT_EQ(host.replies(), "");
  host.wait(400ms);
  EXPECT_EQ(host.replies(), "90 51 FF");
  EXPECT_EQ(host.camera.pan_units(), -264);
  EXPECT_EQ(host.camera.tilt_units(), 120);
  EXPECT_EQ(host.send(visca::pan_tilt_inquiry()), "90 50 0F 0E 0F 08 00 00 07 08 FF");
}

TEST(Evid30Emulator, SlowerSpeedsTakeLongerAndTargetsAreClamped) {
  Host host;
  EXPECT_EQ(host.send(visca::to_camera(std::array<std::uint8_t, 13>{0x01, 0x06, 0x02, 0x0C, 0x0A, 0x00, 0x07, 0x0F,
                                                                     0x0F, 0x00, 0x07, 0x0F, 0x0F})),
            "90 41 FF");  // 0x7FF, 0x7FF: far beyond +100 and +25 degrees; half speeds
  host.wait(1s);
  EXPECT_NEAR(host.camera.pan_units(), 40 * 8.8, 1);
  host.wait(10s);
  EXPECT_EQ(host.camera.pan_units(), visca::kPanMaxUnits);
  EXPECT_EQ(host.camera.tilt_units(), visca::kTiltMaxUnits);
}

TEST(Evid30Emulator, ZoomDirectAndZoomDrive) {
  Host host;
  EXPECT_EQ(host.send(visca::zoom_direct(0x200)), "90 41 FF");
  host.wait(2s);
  EXPECT_EQ(host.replies(), "90 51 FF");
  EXPECT_EQ(host.send(visca::zoom_inquiry()), "90 50 00 02 00 00 FF");
  // Tele at standard speed, then stop: a drive completes at once.
  EXPECT_EQ(host.send({0x81, 0x01, 0x04, 0x07, 0x02, 0xFF}), "90 41 FF | 90 51 FF");
  host.wait(500ms);
  EXPECT_GT(host.camera.zoom_units(), 0x200);
  EXPECT_EQ(host.send({0x81, 0x01, 0x04, 0x07, 0x00, 0xFF}), "90 41 FF | 90 51 FF");
  const double stopped = host.camera.zoom_units();
  host.wait(500ms);
  EXPECT_EQ(host.camera.zoom_units(), stopped);
}

TEST(Evid30Emulator, DrivesUntilStoppedOrAtTheLimit) {
  Host host;
  // Pan left (01), tilt down (02), top speeds; completes at once.
  EXPECT_EQ(host.send(visca::drive_pan_tilt(visca::Drive::forward, visca::Drive::backward, 0x18, 0x14)),
            "90 41 FF | 90 51 FF");
  host.wait(250ms);
  EXPECT_NEAR(host.camera.pan_units(), -20 * 8.8, 1);  // left is camera units falling
  EXPECT_LT(host.camera.tilt_units(), 0);
  host.wait(5s);
  EXPECT_EQ(host.camera.pan_units(), visca::kPanMinUnits);
  EXPECT_EQ(host.camera.tilt_units(), visca::kTiltMinUnits);
  EXPECT_EQ(host.send(visca::drive_pan_tilt(visca::Drive::backward, visca::Drive::stop, 0x18, 0x14)),
            "90 41 FF | 90 51 FF");
  host.wait(100ms);
  EXPECT_EQ(host.send(visca::drive_pan_tilt(visca::Drive::stop, visca::Drive::stop, 0x18, 0x14)), "90 41 FF | 90 51 FF");
  const double pan = host.camera.pan_units();
  host.wait(1s);
  EXPECT_EQ(host.camera.pan_units(), pan);
  EXPECT_GT(pan, visca::kPanMinUnits);
}

TEST(Evid30Emulator, TwoSocketsANewCommandEndsItsKindAndAThirdIsRefused) {
  Host host;
  EXPECT_EQ(host.send(visca::absolute_pan_tilt(800, 0)), "90 41 FF");
  EXPECT_EQ(host.send(visca::zoom_direct(0x3FF)), "90 42 FF");
  EXPECT_EQ(host.camera.busy_sockets(), 2);
  // Another pan/tilt ends the first in socket 1 (completion), then takes it.
  EXPECT_EQ(host.send(visca::absolute_pan_tilt(-800, 0)), "90 51 FF | 90 41 FF");
  // A command of neither kind finds no socket: buffer full.
  EXPECT_EQ(host.send(visca::to_camera(std::array<std::uint8_t, 3>{0x01, 0x04, 0x00})), "90 60 03 FF");
}

TEST(Evid30Emulator, CancelHoldsTheMotionAndDropsItsCompletion) {
  Host host;
  EXPECT_EQ(host.send(visca::absolute_pan_tilt(800, 0)), "90 41 FF");
  host.wait(200ms);
  EXPECT_EQ(host.send(visca::cancel(1)), "90 61 04 FF");
  const double held = host.camera.pan_units();
  EXPECT_GT(held, 100);
  host.wait(3s);
  EXPECT_EQ(host.camera.pan_units(), held);
  EXPECT_EQ(host.replies(), "");  // no completion for a cancelled command
  EXPECT_EQ(host.send(visca::cancel(2)), "90 62 05 FF");
  EXPECT_EQ(host.camera.cancels(), 2u);
}

TEST(Evid30Emulator, OnlyMalformedInputIsASyntaxError) {
  Host host;
  EXPECT_EQ(host.send(visca::absolute_pan_tilt(0, 0, 0x19, 0x14)), "90 60 02 FF");
  EXPECT_EQ(host.send({0x81, 0x01, 0x06, 0x02, 0xFF}), "90 60 02 FF");
  // Noise before a packet is skipped; a packet cut short by a new header is dropped.
  EXPECT_EQ(host.send({0x12, 0x34, 0x81, 0x09, 0x81, 0x09, 0x04, 0x47, 0xFF}), "90 50 00 00 00 00 FF");
  // Power on and others the camera does not model are accepted and completed.
  EXPECT_EQ(host.send({0x81, 0x01, 0x04, 0x00, 0x02, 0xFF}), "90 41 FF | 90 51 FF");
  EXPECT_EQ(host.camera.syntax_errors(), 2u);
  EXPECT_THROW(Evid30Emulator({.pan_top_speed = 0}), std::invalid_argument);
}

}  // namespace
}  // namespace playerkit::emulators
