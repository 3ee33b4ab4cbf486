// Golden bytes from sonyevid30.md: the driver's messages (§2.1, its worked
// examples), the camera's replies (§2.2), the units (§3) and the camera's
// reading of a host's packets (§6.4).

#include "families/sonyevid30/protocol/visca.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "families/sonyevid30/protocol/camera_commands.hpp"
#include "families/sonyevid30/protocol/evid30_units.hpp"

namespace playerkit::hardware::sonyevid30 {
namespace {

std::string hex_of(const Bytes& bytes) { return hex(bytes); }

TEST(Visca, MessagesTheDriverSendsAreTheSheetsBytes) {
  EXPECT_EQ(hex_of(pan_tilt_inquiry()), "81 09 06 12 FF");
  EXPECT_EQ(hex_of(zoom_inquiry()), "81 09 04 47 FF");
  EXPECT_EQ(hex_of(cancel(1)), "81 21 FF");
  EXPECT_EQ(hex_of(cancel(2)), "81 22 FF");
  EXPECT_EQ(hex_of(drive_pan_tilt(Drive::forward, Drive::stop, 0x18, 0x14)), "81 01 06 01 18 14 01 03 FF");
  EXPECT_EQ(hex_of(drive_pan_tilt(Drive::stop, Drive::backward, 0x18, 0x14)), "81 01 06 01 18 14 03 02 FF");
  // Worked example: Player pan +30, tilt +10 (1.5 truncates -264 the same way: 30 x 8.8 is whole).
  EXPECT_EQ(hex_of(absolute_pan_tilt(pan_units(30), tilt_units(10))), "81 01 06 02 18 14 0F 0E 0F 08 00 00 07 08 FF");
  // Worked example: fov 20 with the default limits (3, 30) is 379.3 -> 0x17B.
  EXPECT_EQ(hex_of(zoom_direct(zoom_units(20, {}))), "81 01 04 47 00 01 07 0B FF");
  EXPECT_EQ(hex_of(zoom_direct(5000)), "81 01 04 47 00 03 0F 0F FF");
  EXPECT_EQ(hex_of(to_camera(std::array<std::uint8_t, 3>{0x01, 0x04, 0x00})), "81 01 04 00 FF");
}

TEST(Visca, RepliesAreToldApartBySocket) {
  const Reply acked = parse_reply(ack(2));
  EXPECT_EQ(acked.kind, Reply::Kind::ack);
  EXPECT_EQ(acked.socket, 2);
  const Reply done = parse_reply(completion(1));
  EXPECT_EQ(done.kind, Reply::Kind::completion);
  EXPECT_EQ(done.socket, 1);
  const Reply full = parse_reply(error_reply(0, kBufferFull));
  EXPECT_EQ(full.kind, Reply::Kind::error);
  EXPECT_EQ(full.error_code, kBufferFull);
  EXPECT_EQ(error_text(full.error_code), "command buffer full");
  EXPECT_EQ(parse_reply(error_reply(2, kCancelled)).socket, 2);
  EXPECT_EQ(hex_of(error_reply(1, kNotExecutable)), "90 61 41 FF");
  EXPECT_EQ(parse_reply(Bytes{0x88, 0x30, 0x02, 0xFF}).kind, Reply::Kind::other);
  EXPECT_EQ(parse_reply(Bytes{0x90, 0x41}).kind, Reply::Kind::other);  // no terminator
}

TEST(Visca, InquiryAnswersCarryTwosComplementNibbles) {
  const Bytes reply = pan_tilt_reply({.pan = -264, .tilt = 120});
  EXPECT_EQ(hex_of(reply), "90 50 0F 0E 0F 08 00 00 07 08 FF");
  EXPECT_EQ(reply.size(), kLongestReply);
  const auto units = pan_tilt_answer(parse_reply(reply));
  ASSERT_TRUE(units);
  EXPECT_EQ(units->pan, -264);
  EXPECT_EQ(units->tilt, 120);
  EXPECT_EQ(*zoom_answer(parse_reply(zoom_reply(0x3FF))), 0x3FF);
  EXPECT_EQ(hex_of(zoom_reply(0x17B)), "90 50 00 01 07 0B FF");
  // A high nibble set is no camera's answer.
  EXPECT_FALSE(zoom_answer(parse_reply(Bytes{0x90, 0x50, 0x10, 0x00, 0x00, 0x00, 0xFF})));
  EXPECT_FALSE(pan_tilt_answer(parse_reply(zoom_reply(1))));
}

TEST(Visca, UnitsRoundTripEveryWholeDegree) {
  EXPECT_EQ(pan_units(30), -264);
  EXPECT_EQ(pan_units(100), kPanMinUnits);
  EXPECT_EQ(pan_units(-170), kPanMaxUnits);  // clamped
  EXPECT_EQ(tilt_units(-25), kTiltMinUnits);
  EXPECT_EQ(tilt_units(40), kTiltMaxUnits);
  for (int degrees = -100; degrees <= 100; ++degrees) {
    EXPECT_EQ(std::lround(pan_degrees(pan_units(degrees))), degrees);
  }
  for (int degrees = -25; degrees <= 25; ++degrees) {
    EXPECT_EQ(std::lround(tilt_degrees(tilt_units(degrees))), degrees);
  }
  const FieldOfView limits;
  EXPECT_EQ(zoom_units(30, limits), 0);
  EXPECT_EQ(zoom_units(3, limits), kZoomMaxUnits);
  EXPECT_EQ(zoom_units(0, limits), kZoomMaxUnits);
  EXPECT_EQ(zoom_units(60, limits), 0);
  EXPECT_NEAR(fov_degrees(0x100, limits), 23.25, 1e-9);  // 1.5 printed 24
  for (int fov = 3; fov <= 30; ++fov) EXPECT_EQ(std::lround(fov_degrees(zoom_units(fov, limits), limits)), fov);
}

TEST(Visca, TheCameraReadsWhatTheDriverSends) {
  const HostMessage absolute = parse_host_message(absolute_pan_tilt(-264, 120));
  EXPECT_EQ(absolute.kind, HostMessage::Kind::absolute_pan_tilt);
  EXPECT_EQ(absolute.pan, -264);
  EXPECT_EQ(absolute.tilt, 120);
  EXPECT_EQ(absolute.pan_speed, 0x18);
  const HostMessage drive = parse_host_message(drive_pan_tilt(Drive::backward, Drive::forward, 3, 4));
  EXPECT_EQ(drive.kind, HostMessage::Kind::drive_pan_tilt);
  EXPECT_EQ(drive.drive_pan, Drive::backward);
  EXPECT_EQ(drive.tilt_speed, 4);
  EXPECT_EQ(parse_host_message(zoom_direct(0x17B)).zoom, 0x17B);
  EXPECT_EQ(parse_host_message(zoom_inquiry()).kind, HostMessage::Kind::zoom_inquiry);
  EXPECT_EQ(parse_host_message(pan_tilt_inquiry()).kind, HostMessage::Kind::pan_tilt_inquiry);
  EXPECT_EQ(parse_host_message(cancel(2)).socket, 2);
  EXPECT_EQ(parse_host_message(Bytes{0x88, 0x30, 0x01, 0xFF}).kind, HostMessage::Kind::address_set);
  EXPECT_EQ(parse_host_message(Bytes{0x88, 0x01, 0x00, 0x01, 0xFF}).kind, HostMessage::Kind::if_clear);
  EXPECT_EQ(parse_host_message(Bytes{0x81, 0x01, 0x04, 0x07, 0x23, 0xFF}).zoom_speed, 4);
  EXPECT_EQ(parse_host_message(Bytes{0x81, 0x09, 0x04, 0x00, 0xFF}).kind, HostMessage::Kind::other_inquiry);
  // Speed 0x19 is beyond the pan's 0x18; a short absolute command; nothing at all.
  EXPECT_EQ(parse_host_message(absolute_pan_tilt(0, 0, 0x19, 0x14)).kind, HostMessage::Kind::malformed);
  EXPECT_EQ(parse_host_message(Bytes{0x81, 0x01, 0x06, 0x02, 0x18, 0x14, 0x00, 0xFF}).kind,
            HostMessage::Kind::malformed);
  EXPECT_EQ(parse_host_message(Bytes{0x81, 0xFF}).kind, HostMessage::Kind::malformed);
}

}  // namespace
}  // namespace playerkit::hardware::sonyevid30
