// Behaviour of the generic encoder/decoder that every struct shares. The
// per-interface golden bytes are in messages/*_test.cpp.

#include "protocol/binary_codec.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/all.hpp"

namespace playerkit::protocol {
namespace binary_codec_test {

TEST(BinaryCodec, Int64IsBigEndianAcrossBothHalves) {
  LocalizeSetPose pose;
  pose.subtype = 1;
  pose.cov[0][0] = 0x0102030405060708;
  pose.cov[2][2] = -2;
  const auto bytes = encode(pose);
  ASSERT_EQ(bytes.size(), 85u);
  const std::vector<std::uint8_t> first(bytes.begin() + 13, bytes.begin() + 21);
  EXPECT_EQ(first, (std::vector<std::uint8_t>{1, 2, 3, 4, 5, 6, 7, 8}));
  const std::vector<std::uint8_t> last(bytes.end() - 8, bytes.end());
  EXPECT_EQ(last, (std::vector<std::uint8_t>{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFE}));
  EXPECT_EQ(decode<LocalizeSetPose>(bytes), pose);
}

TEST(BinaryCodec, TruncatedPayloadNamesStructFieldAndSizes) {
  LaserData scan;
  scan.range_count = 3;
  auto bytes = encode(scan);
  bytes.resize(900);
  try {
    (void)decode<LaserData>(bytes);
    FAIL() << "decode accepted a truncated payload";
  } catch (const DecodeError& e) {
    EXPECT_EQ(e.struct_name(), "player_laser_data_t");
    EXPECT_EQ(e.field_name(), "intensity");
    EXPECT_EQ(e.expected(), 1213u);
    EXPECT_EQ(e.got(), 900u);
    EXPECT_STREQ(e.what(),
                 "player_laser_data_t: payload truncated in field 'intensity': expected 1213 bytes, got 900");
  }
}

TEST(BinaryCodec, OversizedPayloadIsRejected) {
  std::vector<std::uint8_t> bytes(26, 0);
  EXPECT_THROW((void)decode<PositionData>(bytes), DecodeError);
  try {
    (void)decode<PositionData>(bytes);
  } catch (const DecodeError& e) {
    EXPECT_STREQ(e.what(), "player_position_data_t: payload too long: expected at most 25 bytes, got 26");
  }
}

TEST(BinaryCodec, CountBeyondCapacityIsRejectedEvenWhenCountComesAfterItsArray) {
  WifiData wifi;
  wifi.link_count = 16;
  auto bytes = encode(wifi);
  ASSERT_EQ(bytes.size(), 658u);
  bytes[609] = 17;  // link_count (offset 608, uint16) follows links[16] on the wire
  wifi.link_count = 17;
  EXPECT_THROW((void)encode(wifi), EncodeError);
  try {
    (void)decode<WifiData>(bytes);
    FAIL() << "accepted link_count 17";
  } catch (const DecodeError& e) {
    EXPECT_EQ(e.field_name(), "links");
  }
}

TEST(BinaryCodec, CountedTailSendsOnlyCountedElements) {
  LocalizeData data;
  data.hypoth_count = 2;
  data.hypoths[0].alpha = 700000;
  data.hypoths[1].alpha = 300000;
  const auto bytes = encode(data);
  EXPECT_EQ(bytes.size(), 14u + 2 * 88u);
  EXPECT_EQ(decode<LocalizeData>(bytes), data);

  data.hypoth_count = 11;
  EXPECT_THROW((void)encode(data), EncodeError);
}

TEST(BinaryCodec, TailVectorHoldsWhatThePayloadHolds) {
  BlobfinderData blobs;
  blobs.width = 80;
  blobs.blobs.resize(2);
  blobs.blobs[1].area = 99;
  const auto bytes = encode(blobs);
  EXPECT_EQ(bytes.size(), 132u + 2 * 22u);
  EXPECT_EQ(decode<BlobfinderData>(bytes), blobs);

  blobs.blobs.resize(321);
  EXPECT_THROW((void)encode(blobs), EncodeError);
}

TEST(BinaryCodec, EncodeToAppends) {
  std::vector<std::uint8_t> out{0xAA};
  PowerData power;
  power.charge = 0x0102;
  encode_to(power, out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{0xAA, 0x01, 0x02}));
}

}  // namespace binary_codec_test
}  // namespace playerkit::protocol
