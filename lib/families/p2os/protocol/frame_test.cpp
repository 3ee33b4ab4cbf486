#include "families/p2os/protocol/frame.hpp"

#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::p2os {
namespace frame_test {

using testing::hex;
namespace golden = testing::golden;

TEST(Checksum, WorkedExamplesOfTheSheet) {
  EXPECT_EQ(checksum(hex("00")), 0x0000);
  EXPECT_EQ(checksum(hex("01")), 0x0001);
  EXPECT_EQ(checksum(hex("04 3B 01 00")), 0x053B);
  EXPECT_EQ(checksum(hex("20 3B 05 05")), 0x2540);
  EXPECT_EQ(checksum(hex("0B 1B 2C 01")), 0x371C);
  EXPECT_EQ(checksum(hex("07 3B")), 0x073B);
}

TEST(Checksum, OddByteIsXoredIntoTheLowByte) {
  // 0x1234 + 0x5678 = 0x68AC, then 0x68AC ^ 0x0F = 0x68A3.
  EXPECT_EQ(checksum(hex("12 34 56 78 0F")), 0x68A3);
  EXPECT_EQ(checksum({}), 0x0000);
}

TEST(Checksum, SumWrapsModulo65536) {
  EXPECT_EQ(checksum(hex("FF FF 00 02")), 0x0001);
}

TEST(BuildFrame, ReproducesEveryWorkedExample) {
  EXPECT_EQ(build_frame(hex("00")), hex(golden::sync0));
  EXPECT_EQ(build_frame(hex("01")), hex(golden::open));
  EXPECT_EQ(build_frame(hex("04 3B 01 00")), hex(golden::enable_1));
  EXPECT_EQ(build_frame(hex("20 3B 05 05")), hex(golden::vel2_right5_left5));
  EXPECT_EQ(build_frame(hex("0B 1B 2C 01")), hex(golden::vel_minus_300));
  EXPECT_EQ(build_frame(hex("07 3B")), hex(golden::seto));
}

TEST(BuildFrame, RefusesEmptyAndOversizedPayloads) {
  EXPECT_THROW(build_frame({}), EncodeError);
  const std::vector<std::uint8_t> largest(251, 0x30);
  EXPECT_EQ(build_frame(largest).size(), 3u + 253u);
  const std::vector<std::uint8_t> too_long(252, 0x30);
  EXPECT_THROW(build_frame(too_long), EncodeError);
}

TEST(FramePayload, ReturnsThePayloadOfAWholeFrame) {
  const auto frame = hex(golden::enable_1);
  const auto payload = frame_payload(frame);
  EXPECT_EQ(std::vector<std::uint8_t>(payload.begin(), payload.end()), hex("04 3B 01 00"));
}

TEST(FramePayload, RejectsMalformedFramesWithAReason) {
  EXPECT_THROW(frame_payload(hex("FA FB 03 00")), DecodeError);            // short
  EXPECT_THROW(frame_payload(hex("FA FC 03 00 00 00")), DecodeError);      // header
  EXPECT_THROW(frame_payload(hex("FA FB 04 00 00 00")), DecodeError);      // length
  EXPECT_THROW(frame_payload(hex("FA FB 06 04 3B 01 00 05 3C")), DecodeError);  // checksum
  try {
    frame_payload(hex("FA FB 06 04 3B 01 00 05 3C"));
  } catch (const DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
  }
}

}  // namespace frame_test
}  // namespace playerkit::hardware::p2os
