#include "families/p2os/protocol/sip.hpp"

#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::p2os {
namespace sip_test {

using testing::hex;
namespace golden = testing::golden;

// The worked SIP of p2os.md §2.3.
StandardSip worked_example() {
  StandardSip sip;
  sip.status = packet_type::sip_stopped;
  sip.x_position = 100;
  sip.y_position = 0;
  sip.heading = 1024;
  sip.battery = 120;
  sip.flags = 1;
  sip.compass = 46;
  sip.sonar = {{0, 500}, {1, 1000}};
  sip.analog_port = 5;
  sip.gripper_state = 0x01;
  return sip;
}

TEST(StandardSip, EncodesTheWorkedExampleByteForByte) {
  EXPECT_EQ(build_frame(encode_sip(worked_example())), hex(golden::sip));
}

TEST(StandardSip, DecodesTheWorkedExample) {
  const StandardSip sip = decode_sip(frame_payload(hex(golden::sip)));
  EXPECT_EQ(sip, worked_example());
  EXPECT_TRUE(sip.motors_enabled());
  EXPECT_EQ(compass_degrees(sip.compass), 90);
}

TEST(StandardSip, RoundTripsEveryField) {
  StandardSip sip;
  sip.status = packet_type::sip_moving;
  sip.x_position = 0xFFFF;
  sip.y_position = 4095;
  sip.heading = -1;
  sip.left_velocity = -32768;
  sip.right_velocity = 32767;
  sip.battery = 255;
  sip.stall_bumpers_low = stall_bumper_byte(true, 0x15);
  sip.stall_bumpers_high = stall_bumper_byte(false, 0x0A);
  sip.control = 0x1234;
  sip.flags = 0x001F;
  sip.compass = 181;
  for (int i = 0; i < 32; ++i) sip.sonar.push_back({static_cast<std::uint8_t>(i), static_cast<std::uint16_t>(i * 1000)});
  sip.analog_port = 3;
  sip.gripper_state = 0x56;
  sip.analog = 200;
  sip.digital_in = 0xA5;
  sip.digital_out = 0x5A;
  sip.trailing = {1, 2, 3};
  const auto payload = encode_sip(sip);
  EXPECT_EQ(payload.size(), kSipFixedSize + 3 * 32 + 3);
  const StandardSip back = decode_sip(payload);
  EXPECT_EQ(back, sip);
  EXPECT_TRUE(back.left_stalled());
  EXPECT_FALSE(back.right_stalled());
  EXPECT_EQ(back.rear_bumpers(), 0x15);
  EXPECT_EQ(back.front_bumpers(), 0x0A);
}

TEST(StandardSip, EveryTruncationIsAClearErrorNeverAnOverread) {
  const auto frame = hex(golden::sip);
  const auto payload = frame_payload(frame);
  for (std::size_t size = 0; size < payload.size(); ++size) {
    EXPECT_THROW(decode_sip(payload.first(size)), DecodeError) << "size " << size;
  }
  EXPECT_NO_THROW(decode_sip(payload));
}

TEST(StandardSip, ASonarCountLargerThanThePayloadNamesTheReadings) {
  const auto frame = hex(golden::sip);
  auto payload = frame_payload(frame);
  std::vector<std::uint8_t> bytes(payload.begin(), payload.end());
  bytes[19] = 40;  // announces 40 readings
  try {
    decode_sip(bytes);
    FAIL();
  } catch (const DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("40 sonar readings"), std::string::npos) << e.what();
  }
}

TEST(StandardSip, RejectsOtherPacketTypes) {
  EXPECT_THROW(decode_sip(hex("98 00")), DecodeError);
  StandardSip sip;
  sip.status = 0x35;
  EXPECT_THROW(encode_sip(sip), EncodeError);
  for (std::uint8_t type = 0x30; type <= 0x34; ++type) {
    sip.status = type;
    EXPECT_EQ(decode_sip(encode_sip(sip)).status, type);
  }
}

TEST(StandardSip, RefusesMoreReadingsThanAFrameHolds) {
  StandardSip sip;
  sip.sonar.resize(76);  // 25 + 228 > 251
  EXPECT_THROW(encode_sip(sip), EncodeError);
  sip.sonar.resize(75);
  EXPECT_NO_THROW(build_frame(encode_sip(sip)));
}

TEST(Compass, SkipsTheBytesTheReferenceIgnores) {
  EXPECT_EQ(compass_degrees(0), std::nullopt);
  EXPECT_EQ(compass_degrees(181), std::nullopt);
  EXPECT_EQ(compass_degrees(255), std::nullopt);
  EXPECT_EQ(compass_degrees(1), 0);
  EXPECT_EQ(compass_degrees(180), 358);
  EXPECT_EQ(compass_degrees(254), 506);
}

TEST(Compass, ByteForAHeadingNeverUsesAnIgnoredValue) {
  EXPECT_EQ(compass_byte(90.0), 46);
  EXPECT_EQ(compass_byte(0.0), 1);
  EXPECT_EQ(compass_byte(-90.0), 136);
  EXPECT_EQ(compass_byte(359.5), 1);  // rounds to 360 = 0
  for (int tenth = -7200; tenth <= 7200; ++tenth) {
    const std::uint8_t b = compass_byte(tenth / 10.0);
    ASSERT_GE(b, 1);
    ASSERT_LE(b, 180);
  }
}

}  // namespace sip_test
}  // namespace playerkit::hardware::p2os
