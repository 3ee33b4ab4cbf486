#include "framing/dle_stuffed_format.hpp"

#include <gtest/gtest.h>

#include "framing/test_support.hpp"

namespace playerkit::framing {
namespace dle_stuffed_format_test {

using namespace test_support;
using Kind = FrameScan::Kind;

// amtecpowercube.md §1: BCC = module id + every data byte (mod 256), the
// id coming from the header: ((D1 & 3) << 3) | (D2 >> 5).
bool amtec_bcc_matches(std::span<const std::uint8_t> content) {
  if (content.size() < 3) return false;
  unsigned sum = static_cast<unsigned>(((content[0] & 0x03) << 3) | (content[1] >> 5));
  for (const std::uint8_t byte : content.subspan(2, content.size() - 3)) sum += byte;
  return static_cast<std::uint8_t>(sum) == content.back();
}

DleStuffedFormat amtec() { return DleStuffedFormat({.check = amtec_bcc_matches, .name = "amtec"}); }

// amtecpowercube.md §1, worked examples.
const Bytes kPanGetPosition = hex("02 05 82 0A 3C 52 03");
const Bytes kTiltGetPosition = hex("02 05 62 0A 3C 51 03");
const Bytes kPanHalt = hex("02 05 81 10 82 0E 03");
const Bytes kPanStep = hex("02 05 88 0B 10 90 DB 0F 49 BF 65 04 82 03");

TEST(DleStuffedFormat, TheSheetsFramesAreWholeWithTheirStuffedLength) {
  const auto format = amtec();
  for (const Bytes& frame : {kPanGetPosition, kTiltGetPosition, kPanHalt, kPanStep}) {
    const FrameScan scan = format.scan(frame);
    EXPECT_EQ(scan.kind, Kind::frame);
    EXPECT_EQ(scan.length, frame.size());
  }
  EXPECT_EQ(format.name(), "amtec");
}

TEST(DleStuffedFormat, UnstuffUndoesTheEscapes) {
  EXPECT_EQ(unstuff(kPanHalt), hex("05 81 02 0E"));
  EXPECT_EQ(unstuff(kPanStep), hex("05 88 0B 10 DB 0F 49 BF 65 04 82"));
  EXPECT_EQ(unstuff(kPanGetPosition), hex("05 82 0A 3C 52"));
  // §6.3: the state "homed" 02 00 00 00 is sent escaped as 10 82 00 00 00.
  EXPECT_EQ(unstuff(hex("02 05 86 0A 27 10 82 00 00 00 3F 03")), hex("05 86 0A 27 02 00 00 00 3F"));
}

TEST(DleStuffedFormat, StuffWritesTheSheetsFrames) {
  EXPECT_EQ(stuff(hex("05 81 02 0E")), kPanHalt);
  EXPECT_EQ(stuff(hex("05 88 0B 10 DB 0F 49 BF 65 04 82")), kPanStep);
  EXPECT_EQ(stuff(hex("05 62 0A 3C 51")), kTiltGetPosition);
}

TEST(DleStuffedFormat, StuffAndUnstuffRoundTripEveryByte) {
  Bytes content = {0x05, 0x03};  // a header holding ETX stays raw
  for (int byte = 0; byte < 256; ++byte) content.push_back(static_cast<std::uint8_t>(byte));
  const Bytes frame = stuff(content);
  EXPECT_EQ(frame.size(), content.size() + 2 + 3);  // STX, ETX, and one DLE for each of 02, 03, 10
  EXPECT_EQ(unstuff(frame), content);
  const DleStuffedFormat unchecked({.max_length = 300});
  EXPECT_EQ(unchecked.scan(frame).kind, Kind::frame);
  EXPECT_EQ(unchecked.scan(frame).length, frame.size());
}

TEST(DleStuffedFormat, HeaderBytesAreNeverFrameEdges) {
  // A module whose D2 is 03 (id 0, 3 data bytes): raw, not an ETX.
  const Bytes frame = stuff(hex("04 03 0A 3C 46"));
  EXPECT_EQ(frame, hex("02 04 03 0A 3C 46 03"));
  const FrameScan scan = DleStuffedFormat().scan(frame);
  EXPECT_EQ(scan.kind, Kind::frame);
  EXPECT_EQ(scan.length, 7u);
}

TEST(DleStuffedFormat, AWrongBccIsABadChecksum) {
  const auto format = amtec();
  const Bytes wrong = hex("02 05 82 0A 3C 53 03");
  EXPECT_EQ(format.scan(wrong).kind, Kind::bad_checksum);
  EXPECT_EQ(format.scan(wrong).length, wrong.size());
  // The driver reads replies without checking (§1.1): no check, no failure.
  EXPECT_EQ(DleStuffedFormat().scan(wrong).kind, Kind::frame);
}

TEST(DleStuffedFormat, NoiseAndSplitReadsStillGiveEveryFrame) {
  const auto format = amtec();
  const auto stream = concat({hex("FF 10 03 00"), kPanHalt, hex("83"), kPanStep, kTiltGetPosition});
  for (const std::size_t piece : {std::size_t{1}, std::size_t{4}, std::size_t{9}, stream.size()}) {
    const Cut result = cut(format, stream, piece);
    ASSERT_EQ(result.frames.size(), 3u) << piece;
    EXPECT_EQ(result.frames[0], kPanHalt);
    EXPECT_EQ(result.frames[1], kPanStep);
    EXPECT_EQ(result.frames[2], kTiltGetPosition);
    EXPECT_EQ(result.skipped, 5u);
    EXPECT_EQ(result.left_over, 0u);
  }
}

TEST(DleStuffedFormat, AFrameThatLostItsEndGivesWayToTheNextStart) {
  const auto format = amtec();
  // The first frame's BCC and ETX are lost.
  const auto stream = concat({hex("02 05 82 0A 3C"), kTiltGetPosition});
  const Cut result = cut(format, stream);
  ASSERT_EQ(result.frames.size(), 1u);
  EXPECT_EQ(result.frames[0], kTiltGetPosition);
  EXPECT_EQ(result.skipped, 5u);
}

TEST(DleStuffedFormat, AnEscapeOfAnOrdinaryByteIsNoFrame) {
  const auto format = amtec();
  EXPECT_EQ(format.scan(hex("02 05 82 10 41 3C 52 03")).kind, Kind::skip);
  EXPECT_EQ(format.scan(hex("02 05 82 10 41 3C 52 03")).length, 1u);
  EXPECT_FALSE(unstuff(hex("02 05 82 10 41 03")));
  // An escape that is the last byte buffered waits for its second half.
  const FrameScan pending = format.scan(hex("02 05 81 10"));
  EXPECT_EQ(pending.kind, Kind::need_more);
  EXPECT_EQ(pending.length, 5u);
}

TEST(DleStuffedFormat, UnstuffRefusesWhatIsNoFrame) {
  EXPECT_FALSE(unstuff(hex("05 82 0A 3C 52 03")));     // no STX
  EXPECT_FALSE(unstuff(hex("02 05 82 0A 3C 52")));     // no ETX
  EXPECT_FALSE(unstuff(hex("02 05 03")));              // shorter than its header
  EXPECT_FALSE(unstuff(hex("02 05 82 0A 02 52 03")));  // a raw STX inside
  EXPECT_FALSE(unstuff(hex("02 05 82 0A 10 03")));     // an escape cut by the ETX
}

TEST(DleStuffedFormat, AFrameWithoutEndIsDroppedAtTheLongestLength) {
  const DleStuffedFormat format({.max_length = 16});
  const auto stream = concat({hex("02 05 82"), Bytes(100, 0x41), kPanHalt});
  for (const std::size_t piece : {std::size_t{1}, std::size_t{50}}) {
    const Cut result = cut(format, stream, piece);
    ASSERT_EQ(result.frames.size(), 1u) << piece;
    EXPECT_EQ(result.frames[0], kPanHalt);
    EXPECT_EQ(result.left_over, 0u);
  }
  // Only noise: nothing waits.
  EXPECT_EQ(cut(format, Bytes(200, 0x41), 9).left_over, 0u);
}

}  // namespace dle_stuffed_format_test
}  // namespace playerkit::framing
