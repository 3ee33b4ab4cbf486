#include "families/sick/protocol/frame_format.hpp"

#include "families/sick/protocol/telegram.hpp"
#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace playerkit::hardware::sick {
namespace frame_format_test {

using testing::bytes;
using Kind = framing::FrameScan::Kind;

const auto kOk = bytes("02 80 03 00 A0 00 10 16 0A");

TEST(SickFrameFormat, FindsAWholeReply) {
  const auto format = SickFrameFormat::replies();
  EXPECT_EQ(format.name(), "sick");
  const framing::FrameScan scan = format.scan(kOk);
  EXPECT_EQ(scan.kind, Kind::frame);
  EXPECT_EQ(scan.length, kOk.size());
}

TEST(SickFrameFormat, AsksForTheBytesItNeeds) {
  const auto format = SickFrameFormat::replies();
  EXPECT_EQ(format.scan({}).kind, Kind::need_more);
  for (std::size_t n = 1; n < kOk.size(); ++n) {
    const framing::FrameScan scan = format.scan(std::span(kOk).first(n));
    EXPECT_EQ(scan.kind, Kind::need_more) << n << " bytes";
    EXPECT_GT(scan.length, n) << n << " bytes";
    EXPECT_LE(scan.length, kOk.size()) << n << " bytes";
  }
}

TEST(SickFrameFormat, SkipsAckNakAndGarbageUpToTheNextStx) {
  const auto format = SickFrameFormat::replies();
  EXPECT_EQ(format.scan(bytes("06 02 80")).kind, Kind::skip);
  EXPECT_EQ(format.scan(bytes("06 02 80")).length, 1u);
  EXPECT_EQ(format.scan(bytes("15")).length, 1u);
  EXPECT_EQ(format.scan(bytes("FF 00 80 13 02 80")).length, 4u);
  EXPECT_EQ(format.scan(bytes("FF 00 80")).length, 3u);
}

TEST(SickFrameFormat, TreatsAnImpossibleHeaderAsNoise) {
  const auto format = SickFrameFormat::replies();
  // A request where a reply is expected, and the other way round.
  EXPECT_EQ(format.scan(bytes("02 00 01 00 3A 1E 12")).kind, Kind::skip);
  EXPECT_EQ(SickFrameFormat::requests().scan(kOk).kind, Kind::skip);
  // LEN 0, a reply of LEN 1 (no status), LEN over the limit.
  EXPECT_EQ(format.scan(bytes("02 80 00 00")).kind, Kind::skip);
  EXPECT_EQ(format.scan(bytes("02 80 01 00")).kind, Kind::skip);
  EXPECT_EQ(format.scan(bytes("02 80 01 04")).kind, Kind::skip);
  EXPECT_EQ(format.scan(bytes("02 80 01 04")).length, 1u);
  EXPECT_EQ(SickFrameFormat::requests().scan(bytes("02 00 00 00")).kind, Kind::skip);
  // The longest allowed body is still waited for.
  EXPECT_EQ(format.scan(bytes("02 80 00 04")).kind, Kind::need_more);
  EXPECT_EQ(format.scan(bytes("02 80 00 04")).length, kHeaderSize + kMaxBodyLength + kCrcSize);
}

TEST(SickFrameFormat, ReportsABadCrcWithTheTelegramsSize) {
  auto corrupt = kOk;
  corrupt.back() ^= 0x01;
  const framing::FrameScan scan = SickFrameFormat::replies().scan(corrupt);
  EXPECT_EQ(scan.kind, Kind::bad_checksum);
  EXPECT_EQ(scan.length, corrupt.size());
}

struct Piece {
  Kind kind;
  std::vector<std::uint8_t> bytes;
};

// What a framed reader does: scan, take what the scan says, repeat.
std::vector<Piece> split(const framing::FrameFormat& format, const std::vector<std::uint8_t>& stream) {
  std::vector<Piece> pieces;
  std::size_t at = 0;
  for (int step = 0; step < 10'000 && at < stream.size(); ++step) {
    const framing::FrameScan scan = format.scan(std::span(stream).subspan(at));
    if (scan.kind == Kind::need_more) break;
    EXPECT_GE(scan.length, 1u);
    pieces.push_back({scan.kind, {stream.begin() + static_cast<std::ptrdiff_t>(at),
                                  stream.begin() + static_cast<std::ptrdiff_t>(at + scan.length)}});
    at += scan.length;
  }
  return pieces;
}

TEST(SickFrameFormat, ResynchronisesOnANoisyLine) {
  const auto type = frame_reply(0xBA, bytes("4C 4D 53 32 30 30"));
  auto corrupt = kOk;
  corrupt[5] = 0x01;
  std::vector<std::uint8_t> stream;
  const auto add = [&](const std::vector<std::uint8_t>& more) {
    stream.insert(stream.end(), more.begin(), more.end());
  };
  add(bytes("06"));            // ACK
  add(kOk);
  add(bytes("FF 02 80 FF 7F"));  // a spurious header with an absurd LEN
  add(corrupt);
  add(bytes("15 02"));         // NAK, a lone STX
  add(type);
  const auto pieces = split(SickFrameFormat::replies(), stream);
  std::vector<std::vector<std::uint8_t>> frames;
  int bad = 0;
  for (const Piece& piece : pieces) {
    if (piece.kind == Kind::frame) frames.push_back(piece.bytes);
    bad += piece.kind == Kind::bad_checksum;
  }
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0], kOk);
  EXPECT_EQ(frames[1], type);
  EXPECT_EQ(bad, 1);
}

}  // namespace frame_format_test
}  // namespace playerkit::hardware::sick
