#include "families/rflex/protocol/rflex_packet.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "families/rflex/protocol/rflex_messages.hpp"

namespace playerkit::hardware::rflex {
namespace rflex_packet_test {

std::vector<std::uint8_t> hex(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::uint8_t> bytes;
  unsigned value = 0;
  while (in >> std::hex >> value) bytes.push_back(static_cast<std::uint8_t>(value));
  return bytes;
}

// The worked examples of rflex.md §1.1.
TEST(RflexPacket, HostCommandsAreTheSheetsBytes) {
  EXPECT_EQ(encode_packet(system_status_request()), hex("1B 02 01 00 01 00 00 1B 03"));
  EXPECT_EQ(encode_packet(set_defaults()), hex("1B 02 02 00 0A 00 08 1B 03"));
  EXPECT_EQ(encode_packet(brake_set()), hex("1B 02 02 00 0B 00 09 1B 03"));
  EXPECT_EQ(encode_packet(brake_release()), hex("1B 02 02 00 0C 00 0E 1B 03"));
  EXPECT_EQ(encode_packet(motion_report_request(100000, 3)),
            hex("1B 02 02 00 22 08 00 01 86 A0 00 00 00 03 0C 1B 03"));
  EXPECT_EQ(encode_packet(dio_reports_request(100000)), hex("1B 02 05 00 00 04 00 01 86 A0 26 1B 03"));
  EXPECT_EQ(encode_packet(sonar_run({30000, 0, 0, 2})),
            hex("1B 02 04 04 00 0D 00 00 75 30 00 00 00 00 00 00 00 00 02 4A 1B 03"));
  EXPECT_EQ(encode_packet(ir_run(true)),
            hex("1B 02 06 00 00 15 00 00 00 00 00 00 00 46 00 00 00 0A 00 00 00 14 00 00 00 96 02 DF 1B 03"));
  EXPECT_EQ(encode_packet(axis_set_direction({kTranslationAxis, 30900, 51500, 30000, true})),
            hex("1B 02 02 00 07 0E 00 00 00 78 B4 00 00 C9 2C 00 00 75 30 01 66 1B 03"));
}

TEST(RflexPacket, RobotReportsAreTheSheetsBytes) {
  const auto odometry = hex(
      "1B 02 02 10 21 19 00 00 00 00 00 00 30 39 00 00 00 04 06 00 00 00 67 00 00 00 00 00 00 00 00 46 1B 03");
  const auto packet = decode_packet(odometry);
  ASSERT_TRUE(packet);
  EXPECT_EQ(read_motion_report(*packet), (MotionReport{12345, 0, 1030, 103}));
  EXPECT_EQ(encode_packet(motion_report({12345, 0, 1030, 103}, 0x10)), odometry);

  const auto status = hex("1B 02 01 11 01 09 00 00 30 39 00 00 0A 50 00 4B 1B 03");
  ASSERT_TRUE(decode_packet(status));
  EXPECT_EQ(read_system_status(*decode_packet(status)), (SystemStatus{12345, 2640, 0}));
  EXPECT_EQ(encode_packet(system_status({12345, 2640, 0}, 0x11)), status);
}

TEST(RflexPacket, EveryReportReadsBackWhatWasBuilt) {
  const std::vector<SonarEcho> echoes{{0, 1476}, {0x11, 65535}, {0x72, 12}};
  EXPECT_EQ(read_sonar_report(*decode_packet(encode_packet(sonar_report(7, echoes, 3)))), echoes);
  EXPECT_EQ(read_dio_report(*decode_packet(encode_packet(dio_report({9, 0x4D, 0x0F}, 1)))),
            (DioReport{9, 0x4D, 0x0F}));
  const std::vector<IrBank> banks{{1, 2, 3, 4, 5, 6, 7, 8}, {9, 10, 11, 12, 13, 14, 15, 255}};
  const auto ir = encode_packet(ir_report(5, banks, 2));
  EXPECT_EQ(ir[11 + 13 + 7], 255);  // reading j of bank b at offset 11 + 13 b + j (§2.2)
  EXPECT_EQ(read_ir_report(*decode_packet(ir)), banks);
  EXPECT_EQ(read_joystick_state(*decode_packet(encode_packet(joystick_state({1, -20, 30, 1}, 0)))),
            (JoystickState{1, -20, 30, 1}));
  EXPECT_EQ(read_sonar_run(sonar_run({3000, 1, 2, 0})), (SonarRun{3000, 1, 2, 0}));
  EXPECT_EQ(read_ir_run(ir_run(false)), false);
  EXPECT_EQ(read_axis_command(axis_set_direction({1, 5, 6, 7, false})), (AxisCommand{1, 5, 6, 7, false}));
  EXPECT_EQ(read_report_request(motion_report_request(0, 0))->period, 0U);
  EXPECT_FALSE(read_motion_report(system_status_request()));
}

TEST(RflexPacket, FramesGoByTheLengthByteNotByEscapes) {
  // A velocity of 0x1B1B1B1B is legal data: no stuffing in either direction.
  const auto bytes = encode_packet(axis_set_direction({0, 0x1B1B1B1B, 0x1B03, 0, true}));
  const RflexFrameFormat format;
  const auto scan = format.scan(bytes);
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(scan.length, bytes.size());
}

TEST(RflexPacket, NoiseBadChecksumsAndShortInputAreTold) {
  const RflexFrameFormat format;
  auto bytes = encode_packet(brake_set());
  EXPECT_EQ(format.scan(std::span(bytes).first(5)).kind, framing::FrameScan::Kind::need_more);
  std::vector<std::uint8_t> noisy{0x55, 0x66, 0x1B};
  noisy.insert(noisy.end(), bytes.begin(), bytes.end());
  EXPECT_EQ(format.scan(noisy).kind, framing::FrameScan::Kind::skip);
  EXPECT_EQ(format.scan(noisy).length, 2U);
  bytes[6] ^= 0xFF;
  EXPECT_EQ(format.scan(bytes).kind, framing::FrameScan::Kind::bad_checksum);
  bytes[6] ^= 0xFF;
  bytes.back() = 0x04;  // not 1B 03: the length byte lied
  EXPECT_EQ(format.scan(bytes).kind, framing::FrameScan::Kind::skip);
  EXPECT_FALSE(decode_packet(bytes));
}

TEST(RflexPacket, EscapeBytesInVelocitiesGoToTheNearestValue) {
  EXPECT_EQ(avoid_escape_bytes(0x00001B10), 0x00001AFFU);
  EXPECT_EQ(avoid_escape_bytes(0x00001B90), 0x00001C00U);
  EXPECT_EQ(avoid_escape_bytes(0x1B000000), 0x1AFFFFFFU);
  EXPECT_EQ(avoid_escape_bytes(0x1B900000), 0x1C000000U);
  EXPECT_EQ(avoid_escape_bytes(35000), 35000U);  // 0x88B8: nothing to avoid
}

}  // namespace rflex_packet_test
}  // namespace playerkit::hardware::rflex
