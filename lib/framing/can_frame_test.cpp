#include "framing/can_frame.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <stdexcept>

#include "framing/test_support.hpp"

// Only to check the layout written by hand against the kernel's own
// definition; the library itself includes nothing but the standard library.
#if __has_include(<linux/can.h>)
#include <linux/can.h>
#define PLAYERKIT_HAVE_LINUX_CAN 1
#endif

namespace playerkit::framing {
namespace can_frame_test {

using namespace test_support;
using Kind = FrameScan::Kind;

// segwayrmp.md §2.2 worked example: xspeed 500 mm/s, yawspeed 10 deg/s ->
// id 0x413, data 00 A4 00 4E 00 00 00 00 (standard id, dlc 8).
const CanFrame kVelocity{.id = 0x413, .dlc = 8, .data = {0x00, 0xA4, 0x00, 0x4E, 0x00, 0x00, 0x00, 0x00}};
const Bytes kVelocityRecord = hex("13 04 00 00 08 00 00 00 00 A4 00 4E 00 00 00 00");
// §2.2: reset all integrators while stopped.
const CanFrame kResetIntegrators{.id = 0x413, .dlc = 8, .data = {0x00, 0x00, 0x00, 0x00, 0x00, 0x32, 0x0F, 0x0F}};

Bytes record_of(const CanFrame& frame) {
  const auto record = encode_can_frame(frame);
  return Bytes(record.begin(), record.end());
}

TEST(CanFrame, TheRmpVelocityCommandAsAKernelRecord) {
  EXPECT_EQ(record_of(kVelocity), kVelocityRecord);
  EXPECT_EQ(decode_can_frame(kVelocityRecord), kVelocity);
}

TEST(CanFrame, ExtendedAndRemoteFlagsGoInTheTopBits) {
  const CanFrame extended{.id = 0x18FF1234, .extended = true, .dlc = 2, .data = {0xAB, 0xCD}};
  EXPECT_EQ(record_of(extended), hex("34 12 FF 98 02 00 00 00 AB CD 00 00 00 00 00 00"));
  const CanFrame remote{.id = 0x400, .remote = true, .dlc = 8};
  EXPECT_EQ(record_of(remote), hex("00 04 00 40 08 00 00 00 00 00 00 00 00 00 00 00"));
  EXPECT_EQ(decode_can_frame(record_of(extended)), extended);
  EXPECT_EQ(decode_can_frame(record_of(remote)), remote);
}

TEST(CanFrame, RoundTripsEveryLengthAndBothIdSizes) {
  for (std::uint8_t dlc = 0; dlc <= 8; ++dlc) {
    for (const bool extended : {false, true}) {
      CanFrame frame{.id = extended ? 0x1ABCDEF0u : 0x7FFu, .extended = extended, .dlc = dlc};
      for (std::uint8_t i = 0; i < dlc; ++i) frame.data[i] = static_cast<std::uint8_t>(0xF0 + i);
      const auto record = record_of(frame);
      EXPECT_EQ(record[4], dlc);
      EXPECT_EQ(decode_can_frame(record), frame) << int{dlc} << " " << extended;
    }
  }
}

TEST(CanFrame, EncodingRefusesFramesNoBusCarries) {
  EXPECT_THROW((void)encode_can_frame({.id = 0x800}), std::invalid_argument);
  EXPECT_THROW((void)encode_can_frame({.id = 0x20000000, .extended = true}), std::invalid_argument);
  EXPECT_THROW((void)encode_can_frame({.id = 0x413, .dlc = 9}), std::invalid_argument);
  EXPECT_NO_THROW((void)encode_can_frame({.id = 0x1FFFFFFF, .extended = true, .dlc = 8}));
}

TEST(CanFrame, DecodingRefusesRecordsThatHoldNoFrame) {
  EXPECT_FALSE(decode_can_frame(hex("13 04 00 00 09 00 00 00 00 00 00 00 00 00 00 00")));  // dlc 9
  EXPECT_FALSE(decode_can_frame(hex("00 08 00 00 08 00 00 00 00 00 00 00 00 00 00 00")));  // standard id 0x800
  EXPECT_FALSE(decode_can_frame(hex("04 00 00 20 08 00 00 00 00 00 00 00 00 00 00 00")));  // error frame
  EXPECT_FALSE(decode_can_frame(hex("13 04 00 00 08 00 00 00")));                          // short
  // Bytes past dlc are not part of the frame.
  const auto decoded = decode_can_frame(hex("13 04 00 00 02 00 00 00 11 22 33 44 55 66 77 88"));
  ASSERT_TRUE(decoded);
  EXPECT_EQ(decoded->data, (std::array<std::uint8_t, 8>{0x11, 0x22}));
}

#ifdef PLAYERKIT_HAVE_LINUX_CAN
TEST(CanFrame, TheLayoutIsTheKernelsStructCanFrame) {
  static_assert(sizeof(struct can_frame) == kCanRecordSize);
  static_assert(CAN_EFF_FLAG == kCanExtendedFlag && CAN_RTR_FLAG == kCanRemoteFlag && CAN_ERR_FLAG == kCanErrorFlag);
  static_assert(CAN_SFF_MASK == kCanStandardIdMask && CAN_EFF_MASK == kCanExtendedIdMask);
  if constexpr (std::endian::native != std::endian::little) GTEST_SKIP() << "the encoding is little-endian";
  struct can_frame kernel {};
  kernel.can_id = 0x18FF1234 | CAN_EFF_FLAG;
  kernel.len = 3;
  kernel.data[0] = 0x01;
  kernel.data[1] = 0x02;
  kernel.data[2] = 0x03;
  Bytes raw(kCanRecordSize);
  std::memcpy(raw.data(), &kernel, kCanRecordSize);
  EXPECT_EQ(record_of({.id = 0x18FF1234, .extended = true, .dlc = 3, .data = {1, 2, 3}}), raw);
}
#endif

TEST(CanRecordFormat, CutsAStreamIntoRecords) {
  const CanRecordFormat format;
  EXPECT_EQ(format.name(), "can");
  const auto stream = concat({kVelocityRecord, record_of(kResetIntegrators)});
  for (const std::size_t piece : {std::size_t{1}, std::size_t{5}, std::size_t{16}, stream.size()}) {
    const Cut result = cut(format, stream, piece);
    ASSERT_EQ(result.frames.size(), 2u) << piece;
    EXPECT_EQ(decode_can_frame(result.frames[0]), kVelocity);
    EXPECT_EQ(decode_can_frame(result.frames[1]), kResetIntegrators);
    EXPECT_EQ(result.left_over, 0u);
  }
  EXPECT_EQ(format.scan({}).length, 16u);
  EXPECT_EQ(format.scan(hex("13 04")).kind, Kind::need_more);
}

TEST(CanRecordFormat, ARecordHoldingNoFrameIsDroppedWholeKeepingAlignment) {
  const CanRecordFormat format;
  const auto error_frame = hex("04 00 00 20 08 00 00 00 00 00 00 00 00 00 00 00");
  const Cut result = cut(format, concat({error_frame, kVelocityRecord}), 7);
  ASSERT_EQ(result.frames.size(), 1u);
  EXPECT_EQ(result.frames[0], kVelocityRecord);
  EXPECT_EQ(result.skipped, 16u);
  // Endless garbage never waits beyond one record.
  EXPECT_LT(cut(format, Bytes(1000, 0xFF), 9).left_over, 16u);
}

}  // namespace can_frame_test
}  // namespace playerkit::framing
