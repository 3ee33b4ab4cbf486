#include "families/flockofbirds/protocol/bird_record.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "framing/phasing_bit_format.hpp"

namespace playerkit::hardware::flockofbirds {
namespace bird_record_test {

// flockofbirds.md §1.1's worked example: X 12", Y -6", Z 3", az 90, el -45, roll 10.
const BirdPose kSheetPose{.x_mm = 304.8, .y_mm = -152.4, .z_mm = 76.2, .azimuth_deg = 90, .elevation_deg = -45, .roll_deg = 10};
const Record kSheetRecord{0xAA, 0x15, 0x2A, 0x75, 0x2A, 0x05, 0x00, 0x20, 0x00, 0x70, 0x47, 0x03};

TEST(BirdRecord, TheSheetsWorkedExampleByteForByte) {
  const RecordWords words = words_from_pose(kSheetPose, PositionScaling::inches_36);
  const RecordWords expected{0x2AAB, static_cast<std::int16_t>(0xEAAB), 0x0AAB, 0x4000, static_cast<std::int16_t>(0xE000), 0x071C};
  EXPECT_EQ(words, expected);
  EXPECT_EQ(encode_record(words), kSheetRecord);
}

TEST(BirdRecord, DecodesTheSheetsRecordLosingTheTwoLowBits) {
  const auto words = decode_record(kSheetRecord);
  ASSERT_TRUE(words);
  EXPECT_EQ(*words, (RecordWords{10920, -5464, 2728, 16384, -8192, 1820}));
  const BirdPose pose = pose_from_words(*words, PositionScaling::inches_36);
  // Ascension's full scale, W / 32768 (1.5 divided by 32767: 304.73 mm, 90.0027 deg).
  EXPECT_NEAR(pose.x_mm, 304.72, 0.01);
  EXPECT_NEAR(pose.y_mm, -152.47, 0.01);
  EXPECT_NEAR(pose.z_mm, 76.12, 0.01);
  EXPECT_DOUBLE_EQ(pose.azimuth_deg, 90.0);
  EXPECT_DOUBLE_EQ(pose.elevation_deg, -45.0);
  EXPECT_NEAR(pose.roll_deg, 9.9976, 1e-4);
}

TEST(BirdRecord, SeventyTwoInchScalingDoublesPositionsNotAngles) {
  const auto words = decode_record(kSheetRecord);
  const BirdPose pose = pose_from_words(*words, PositionScaling::inches_72);
  EXPECT_NEAR(pose.x_mm, 609.45, 0.01);
  EXPECT_DOUBLE_EQ(pose.azimuth_deg, 90.0);
  EXPECT_EQ(full_scale_inches(PositionScaling::inches_72), 72);
  EXPECT_DOUBLE_EQ(full_scale_mm(PositionScaling::inches_72), 1828.8);
}

TEST(BirdRecord, WordsKeepTheirSignAndLoseOnlyTheLowBits) {
  for (const int value : {-32768, -32767, -5, -4, -1, 0, 1, 3, 4, 1000, 32764, 32767}) {
    const auto [ls, ms] = encode_word(static_cast<std::int16_t>(value));
    EXPECT_EQ(ls & kPhasingBit, 0);
    EXPECT_EQ(ms & kPhasingBit, 0);
    EXPECT_EQ(decode_word(ls, ms), static_cast<std::int16_t>(value & ~3)) << value;
  }
}

TEST(BirdRecord, PosesBeyondFullScaleAreClamped) {
  const BirdPose far{.x_mm = 5000, .y_mm = -5000, .z_mm = 0, .azimuth_deg = 180, .elevation_deg = -180, .roll_deg = 0};
  const RecordWords words = words_from_pose(far, PositionScaling::inches_36);
  EXPECT_EQ(words[0], 32767);
  EXPECT_EQ(words[1], -32768);
  EXPECT_EQ(words[3], 32767);
  EXPECT_EQ(words[4], -32768);
}

TEST(BirdRecord, RefusesWhatIsNoRecord) {
  Record unmarked = kSheetRecord;
  unmarked[0] &= 0x7F;
  EXPECT_EQ(decode_record(unmarked), std::nullopt);
  Record marked_inside = kSheetRecord;
  marked_inside[5] |= kPhasingBit;
  EXPECT_EQ(decode_record(marked_inside), std::nullopt);
  EXPECT_EQ(decode_record(std::span(kSheetRecord).first(11)), std::nullopt);
}

TEST(BirdRecord, RecordsAreCutOnTheirPhasingBitBehindNoiseAndAShortRecord) {
  const framing::PhasingBitFormat format(record_format_options());
  std::vector<std::uint8_t> stream{0x01, 0x02};                          // the tail of a record
  stream.insert(stream.end(), kSheetRecord.begin(), kSheetRecord.begin() + 5);  // cut short
  stream.insert(stream.end(), kSheetRecord.begin(), kSheetRecord.end());
  auto scan = format.scan(stream);
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::skip);
  EXPECT_EQ(scan.length, 2u);
  scan = format.scan(std::span(stream).subspan(2));
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::skip);
  EXPECT_EQ(scan.length, 5u);
  scan = format.scan(std::span(stream).subspan(7));
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(scan.length, kRecordSize);
}

}  // namespace bird_record_test
}  // namespace playerkit::hardware::flockofbirds
