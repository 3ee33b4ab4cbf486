#include "framing/fixed_length_format.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "framing/test_support.hpp"

namespace playerkit::framing {
namespace fixed_length_format_test {

using namespace test_support;
using Kind = FrameScan::Kind;

// er1.md §1.1: the checksum byte makes the sum of all bytes 0 (mod 256).
bool er1_sum_is_zero(std::span<const std::uint8_t> telegram) {
  return std::accumulate(telegram.begin(), telegram.end(), 0u) % 256 == 0;
}

// trogdor.md §1.2: after the ACK byte (6), GET_ODOM's 18 bytes end with the
// XOR of the 17 before them.
bool trogdor_xor_matches(std::span<const std::uint8_t> telegram) {
  std::uint8_t sum = 0;
  for (const std::uint8_t byte : telegram.subspan(1, telegram.size() - 2)) sum ^= byte;
  return sum == telegram.back();
}

FixedLengthFormat er1_commands() { return FixedLengthFormat({.size = 8, .check = er1_sum_is_zero, .name = "er1"}); }

FixedLengthFormat trogdor_odometry() {
  return FixedLengthFormat({.size = 19, .sync = {0x06}, .check = trogdor_xor_matches, .name = "trogdor"});
}

// Computed from trogdor.md §1.2's layout: ACK, left 1000, right -1000,
// right velocity 5, left velocity -5 (int32 LE), error 0, XOR.
const Bytes kOdometry = hex("06 E8 03 00 00 18 FC FF FF 05 00 00 00 FB FF FF FF 00 0E");

TEST(FixedLengthFormat, Er1CommandsFromTheSheetPassTheirSum) {
  const auto format = er1_commands();
  EXPECT_EQ(format.name(), "er1");
  // er1.md §1.1 worked example (motor 0 and motor 1) and §2's RESET_5.
  for (const std::string_view command :
       {"00 8B 00 11 FF FD 6E FA", "01 8A 00 11 FF FD 6E FA", "00 EF 00 11 00 00 00 00"}) {
    const FrameScan scan = format.scan(hex(command));
    EXPECT_EQ(scan.kind, Kind::frame) << command;
    EXPECT_EQ(scan.length, 8u);
  }
  // §2: ACCL_3's checksum is wrong in the reference (sum 0xFC).
  EXPECT_EQ(format.scan(hex("00 F2 00 90 00 00 00 7A")).kind, Kind::bad_checksum);
}

TEST(FixedLengthFormat, WithoutSyncEveryByteMayStartATelegram) {
  const auto format = er1_commands();
  EXPECT_EQ(format.scan(hex("00 8B 00 11")).kind, Kind::need_more);
  EXPECT_EQ(format.scan(hex("00 8B 00 11")).length, 8u);
  EXPECT_EQ(format.scan({}).length, 8u);
  // Back to back, cut at any size.
  const auto stream = hex("00 8B 00 11 FF FD 6E FA 01 8A 00 11 FF FD 6E FA");
  for (const std::size_t piece : {std::size_t{1}, std::size_t{3}, std::size_t{16}}) {
    const Cut result = cut(format, stream, piece);
    ASSERT_EQ(result.frames.size(), 2u);
    EXPECT_EQ(result.frames[1], hex("01 8A 00 11 FF FD 6E FA"));
  }
}

TEST(FixedLengthFormat, TrogdorOdometryBehindItsAck) {
  const auto format = trogdor_odometry();
  EXPECT_EQ(format.scan(kOdometry).kind, Kind::frame);
  EXPECT_EQ(format.scan(kOdometry).length, 19u);
  // The encoder error byte set, XOR not updated.
  Bytes damaged = kOdometry;
  damaged[17] = 0x01;
  EXPECT_EQ(format.scan(damaged).kind, Kind::bad_checksum);
  damaged[18] = 0x0F;
  EXPECT_EQ(format.scan(damaged).kind, Kind::frame);
}

TEST(FixedLengthFormat, NoiseBeforeTheSyncIsSkipped) {
  const auto format = trogdor_odometry();
  // A NACK (21) and line noise, then the ACK and the odometry.
  const auto stream = concat({hex("15 00 FF 42"), kOdometry});
  for (const std::size_t piece : {std::size_t{1}, std::size_t{5}, stream.size()}) {
    const Cut result = cut(format, stream, piece);
    ASSERT_EQ(result.frames.size(), 1u) << piece;
    EXPECT_EQ(result.frames[0], kOdometry);
    EXPECT_EQ(result.skipped, 4u);
    EXPECT_EQ(result.left_over, 0u);
  }
}

TEST(FixedLengthFormat, AMultiByteSyncIsHuntedInsideAFalseStart) {
  // rflex.md's start pattern 1B 02, here on made-up 6-byte telegrams.
  const FixedLengthFormat format({.size = 6, .sync = {0x1b, 0x02}});
  EXPECT_EQ(format.scan(hex("1B")).kind, Kind::need_more);
  EXPECT_EQ(format.scan(hex("1B 03")).kind, Kind::skip);
  const auto stream = hex("1B 1B 02 AA BB CC DD 1B 02 01 02 03 04");
  const Cut result = cut(format, stream);
  ASSERT_EQ(result.frames.size(), 2u);
  EXPECT_EQ(result.frames[0], hex("1B 02 AA BB CC DD"));
  EXPECT_EQ(result.frames[1], hex("1B 02 01 02 03 04"));
  EXPECT_EQ(result.skipped, 1u);
}

TEST(FixedLengthFormat, EndlessNoiseIsNeverKept) {
  const auto format = trogdor_odometry();
  const Cut result = cut(format, Bytes(500, 0x55), 7);
  EXPECT_TRUE(result.frames.empty());
  EXPECT_EQ(result.left_over, 0u);
  EXPECT_EQ(result.skipped, 500u);
}

TEST(FixedLengthFormat, ASizeBelowTheSyncGrowsToIt) {
  const FixedLengthFormat format({.size = 1, .sync = {0xAA, 0x55}});
  EXPECT_EQ(format.scan(hex("AA 55")).kind, Kind::frame);
  EXPECT_EQ(format.scan(hex("AA 55")).length, 2u);
}

}  // namespace fixed_length_format_test
}  // namespace playerkit::framing
