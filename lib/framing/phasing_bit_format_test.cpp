#include "framing/phasing_bit_format.hpp"

#include <gtest/gtest.h>

#include "framing/test_support.hpp"

namespace playerkit::framing {
namespace phasing_bit_format_test {

using namespace test_support;
using Kind = FrameScan::Kind;

// flockofbirds.md §1.1, worked example: X 12", Y -6", Z 3", az 90°, el -45°, roll 10°.
const Bytes kRecord = hex("AA 15 2A 75 2A 05 00 20 00 70 47 03");
// The same layout with every word 0: the phasing bit alone.
const Bytes kZeroRecord = hex("80 00 00 00 00 00 00 00 00 00 00 00");

TEST(PhasingBitFormat, TheSheetsRecordIsWhole) {
  const PhasingBitFormat format;
  EXPECT_EQ(format.name(), "phasing");
  const FrameScan scan = format.scan(kRecord);
  EXPECT_EQ(scan.kind, Kind::frame);
  EXPECT_EQ(scan.length, 12u);
  EXPECT_EQ(format.scan(Bytes(kRecord.begin(), kRecord.begin() + 5)).length, 12u);  // need_more up to a record
}

TEST(PhasingBitFormat, AStreamOfRecordsCutAnywhere) {
  const PhasingBitFormat format;
  const auto stream = concat({kRecord, kZeroRecord, kRecord});
  for (const std::size_t piece : {std::size_t{1}, std::size_t{5}, std::size_t{12}, stream.size()}) {
    const Cut result = cut(format, stream, piece);
    EXPECT_EQ(result.frames, (std::vector<Bytes>{kRecord, kZeroRecord, kRecord})) << piece;
    EXPECT_EQ(result.left_over, 0u);
  }
}

TEST(PhasingBitFormat, BytesBeforeTheFirstPhasingByteAreDropped) {
  // flockofbirds.md §5: bytes before the first phasing byte are dropped
  // (joining a stream mid-record).
  const PhasingBitFormat format;
  const auto stream = concat({Bytes(kRecord.begin() + 7, kRecord.end()), kRecord});
  const Cut result = cut(format, stream);
  EXPECT_EQ(result.frames, std::vector<Bytes>{kRecord});
  EXPECT_EQ(result.skipped, 5u);
}

TEST(PhasingBitFormat, APhasingByteInsideRestartsTheRecord) {
  // §5: bytes with bit 7 set always restart a record. The first record lost its tail.
  const PhasingBitFormat format;
  const auto stream = concat({Bytes(kRecord.begin(), kRecord.begin() + 6), kZeroRecord});
  const Cut result = cut(format, stream, 4);
  EXPECT_EQ(result.frames, std::vector<Bytes>{kZeroRecord});
  EXPECT_EQ(result.skipped, 6u);
}

TEST(PhasingBitFormat, OnlyUnmarkedBytesAreNeverKept) {
  const PhasingBitFormat format;
  const Cut result = cut(format, Bytes(100, 0x7F), 9);
  EXPECT_TRUE(result.frames.empty());
  EXPECT_EQ(result.left_over, 0u);
}

TEST(PhasingBitFormat, OtherSizesAndMarkers) {
  const PhasingBitFormat format({.record_size = 3, .phasing_mask = 0x40, .name = "three"});
  EXPECT_EQ(format.name(), "three");
  const Cut result = cut(format, hex("01 41 02 03 40 3F 00"));
  EXPECT_EQ(result.frames, (std::vector<Bytes>{hex("41 02 03"), hex("40 3F 00")}));
  EXPECT_EQ(result.skipped, 1u);
}

}  // namespace phasing_bit_format_test
}  // namespace playerkit::framing
