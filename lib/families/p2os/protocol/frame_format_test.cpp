#include "families/p2os/protocol/frame_format.hpp"

#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace playerkit::hardware::p2os {
namespace frame_format_test {

using testing::hex;
namespace golden = testing::golden;
using Kind = framing::FrameScan::Kind;

// What a reader does with a format: returns the whole frames found in
// `stream`, counting checksum failures and skipped bytes. A bad frame is
// dropped whole, as the reference does.
struct Split {
  std::vector<std::vector<std::uint8_t>> frames;
  int bad_checksums = 0;
  std::size_t skipped = 0;
  std::size_t left_over = 0;
};

Split split(const framing::FrameFormat& format, const std::vector<std::uint8_t>& stream) {
  Split result;
  std::vector<std::uint8_t> buffer;
  // Byte by byte: the worst case for a format's need_more logic.
  for (std::uint8_t byte : stream) {
    buffer.push_back(byte);
    for (int guard = 0; guard < 1000 && !buffer.empty(); ++guard) {
      const framing::FrameScan scan = format.scan(buffer);
      if (scan.kind == Kind::need_more) break;
      EXPECT_GE(scan.length, 1u);
      EXPECT_LE(scan.length, buffer.size());
      if (scan.kind == Kind::frame) result.frames.emplace_back(buffer.begin(), buffer.begin() + static_cast<long>(scan.length));
      if (scan.kind == Kind::bad_checksum) ++result.bad_checksums;
      if (scan.kind == Kind::skip) result.skipped += scan.length;
      buffer.erase(buffer.begin(), buffer.begin() + static_cast<long>(scan.length));
    }
  }
  result.left_over = buffer.size();
  return result;
}

std::vector<std::uint8_t> concat(std::initializer_list<std::vector<std::uint8_t>> parts) {
  std::vector<std::uint8_t> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

TEST(P2osFrameFormat, FindsEveryWorkedExample) {
  const P2osFrameFormat format;
  EXPECT_EQ(format.name(), "p2os");
  for (std::string_view example : {golden::sync0, golden::open, golden::enable_1,
                                   golden::vel2_right5_left5, golden::vel_minus_300, golden::seto,
                                   golden::sync2_myrobot, golden::sip}) {
    const auto bytes = hex(example);
    const framing::FrameScan scan = format.scan(bytes);
    EXPECT_EQ(scan.kind, Kind::frame) << example;
    EXPECT_EQ(scan.length, bytes.size()) << example;
  }
}

TEST(P2osFrameFormat, AsksForExactlyTheMissingBytes) {
  const P2osFrameFormat format;
  const auto sip = hex(golden::sip);
  EXPECT_EQ(format.scan(std::span(sip).first(0)).kind, Kind::need_more);
  EXPECT_EQ(format.scan(std::span(sip).first(1)).length, 2u);
  EXPECT_EQ(format.scan(std::span(sip).first(2)).length, 3u);
  const framing::FrameScan partial = format.scan(std::span(sip).first(10));
  EXPECT_EQ(partial.kind, Kind::need_more);
  EXPECT_EQ(partial.length, sip.size());
}

TEST(P2osFrameFormat, SkipsGarbageUpToTheNextHeaderByte) {
  const P2osFrameFormat format;
  const auto bytes = hex("01 02 03 FA FB 03 00 00 00");
  const framing::FrameScan scan = format.scan(bytes);
  EXPECT_EQ(scan.kind, Kind::skip);
  EXPECT_EQ(scan.length, 3u);
  const framing::FrameScan lone_fa = format.scan(hex("FA 00 FA FB"));
  EXPECT_EQ(lone_fa.kind, Kind::skip);
  EXPECT_EQ(lone_fa.length, 1u);
}

TEST(P2osFrameFormat, ReportsABadChecksumWithTheFrameLength) {
  const P2osFrameFormat format;
  auto bytes = hex(golden::enable_1);
  bytes.back() ^= 0x01;
  const framing::FrameScan scan = format.scan(bytes);
  EXPECT_EQ(scan.kind, Kind::bad_checksum);
  EXPECT_EQ(scan.length, bytes.size());
}

TEST(P2osFrameFormat, ChecksTheWholeSumUnlikeTheReference) {
  // The reference's weak test passes any frame whose last byte is non-zero
  // (quirk 1); here a wrong high byte with a non-zero low byte still fails.
  const P2osFrameFormat format;
  auto bytes = hex(golden::enable_1);
  bytes[bytes.size() - 2] = 0x00;
  EXPECT_EQ(format.scan(bytes).kind, Kind::bad_checksum);
}

TEST(P2osFrameFormat, TreatsAbsurdLengthsAsNoise) {
  const P2osFrameFormat from_robot;
  EXPECT_EQ(from_robot.scan(hex("FA FB 00 00")).kind, Kind::skip);
  EXPECT_EQ(from_robot.scan(hex("FA FB 02 00 00")).kind, Kind::skip);
  EXPECT_EQ(from_robot.scan(hex("FA FB FE")).kind, Kind::skip);
  EXPECT_EQ(from_robot.scan(hex("FA FB FD")).kind, Kind::need_more);
  const P2osFrameFormat to_robot(kMaxLengthByteToRobot);
  EXPECT_EQ(to_robot.scan(hex("FA FB C9")).kind, Kind::skip);
  EXPECT_EQ(to_robot.scan(hex("FA FB C8")).kind, Kind::need_more);
}

TEST(P2osFrameFormat, ResynchronisesThroughNoiseAndCorruptFrames) {
  const P2osFrameFormat format;
  auto corrupt = hex(golden::vel_minus_300);
  corrupt[5] ^= 0x40;
  const auto stream = concat({hex("00 13 FA FA"), hex(golden::sync0), hex("FB FB 77"),
                              corrupt, hex("FA FB 01"), hex(golden::enable_1), hex(golden::sip)});
  const Split result = split(format, stream);
  ASSERT_EQ(result.frames.size(), 3u);
  EXPECT_EQ(result.frames[0], hex(golden::sync0));
  EXPECT_EQ(result.frames[1], hex(golden::enable_1));
  EXPECT_EQ(result.frames[2], hex(golden::sip));
  EXPECT_EQ(result.bad_checksums, 1);
  EXPECT_EQ(result.left_over, 0u);
}

}  // namespace frame_format_test
}  // namespace playerkit::hardware::p2os
