#include "families/p2os/protocol/gyro_packet.hpp"

#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::p2os {
namespace gyro_packet_test {

using testing::hex;

TEST(GyroPacket, LayoutIsTypeCountThenTriples) {
  const GyroPacket packet{{{512, 30}, {0x0123, 31}}};
  EXPECT_EQ(encode_gyro_packet(packet), hex("98 02 00 02 1E 23 01 1F"));
  EXPECT_EQ(decode_gyro_packet(hex("98 02 00 02 1E 23 01 1F")), packet);
}

TEST(GyroPacket, AverageIsRoundedLikeTheReference) {
  EXPECT_EQ((GyroPacket{{{512, 0}, {513, 0}}}.average_rate()), 513);  // 512.5 rounds up
  EXPECT_EQ((GyroPacket{{{500, 0}, {510, 0}, {511, 0}}}.average_rate()), 507);
  EXPECT_EQ(GyroPacket{}.average_rate(), std::nullopt);
}

TEST(GyroPacket, CountMustMatchTheLength) {
  EXPECT_THROW(decode_gyro_packet(hex("98 02 00 02 1E 23 01")), DecodeError);
  EXPECT_THROW(decode_gyro_packet(hex("98 01 00 02 1E 23")), DecodeError);
  EXPECT_THROW(decode_gyro_packet(hex("98")), DecodeError);
  EXPECT_THROW(decode_gyro_packet(hex("32 00")), DecodeError);
  EXPECT_EQ(decode_gyro_packet(hex("98 00")).readings.size(), 0u);
}

TEST(GyroPacket, RefusesMoreReadingsThanAFrameHolds) {
  GyroPacket packet;
  packet.readings.resize(83);  // 2 + 249 = 251 payload bytes: the largest frame
  EXPECT_NO_THROW(build_frame(encode_gyro_packet(packet)));
  packet.readings.resize(84);
  EXPECT_THROW(encode_gyro_packet(packet), EncodeError);
}

}  // namespace gyro_packet_test
}  // namespace playerkit::hardware::p2os
