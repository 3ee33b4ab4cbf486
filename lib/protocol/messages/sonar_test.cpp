// Golden-byte tests of the `sonar` interface (wire-format.md §5 "sonar").

#include "protocol/messages/sonar.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace sonar_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(SonarData::kWireSize == 130);        // player_sonar_data_t
static_assert(SonarGeom::kWireSize == 387);        // player_sonar_geom_t
static_assert(SonarPowerConfig::kWireSize == 2);   // player_sonar_power_config_t

SonarData three_ranges() {
  SonarData d{.range_count = 3};
  d.ranges[0] = 0x0102;
  d.ranges[1] = 0x0304;
  d.ranges[2] = 0x0506;
  return d;
}

Bytes three_ranges_bytes() {
  return WireBytes(130)
      .at(0, {0x00, 0x03})  // range_count @0 uint16 = 3
      .at(2, {0x01, 0x02})  // ranges[0]   @2 uint16
      .at(4, {0x03, 0x04})  // ranges[1]   @4
      .at(6, {0x05, 0x06})  // ranges[2]   @6
      .zeros(8, 61 * 2)     // ranges[3..63] @8..129, unused
      .done();
}

TEST(SonarGolden, DataPacketWithThreeReadings) {
  EXPECT_TRUE(EncodesTo(three_ranges(), three_ranges_bytes()));
  EXPECT_TRUE(DecodesTo(three_ranges_bytes(), three_ranges()));
  const auto j = to_json(three_ranges());
  EXPECT_TRUE(golden::HasFields(j, {"range_count", "ranges"}));
  EXPECT_EQ(j.at("range_count"), 3);
  EXPECT_EQ(j.at("ranges"), (nlohmann::json{0x0102, 0x0304, 0x0506}));
  EXPECT_TRUE(SurvivesJson(three_ranges()));
}

TEST(SonarGolden, DataPacketWithAll64Readings) {
  SonarData full{.range_count = 64};
  WireBytes wire(130);
  wire.at(0, {0x00, 0x40});  // range_count @0 = 64
  for (std::size_t i = 0; i < 64; ++i) {
    // ranges[i] @2+2i: high byte 0x11+i, low byte 0x80+i
    full.ranges[i] = static_cast<std::uint16_t>(((0x11 + i) << 8) | (0x80 + i));
    wire.at(2 + 2 * i, {static_cast<std::uint8_t>(0x11 + i), static_cast<std::uint8_t>(0x80 + i)});
  }
  const Bytes golden_bytes = wire.done();
  EXPECT_EQ(golden_bytes[2], 0x11);    // ranges[0] high byte first
  EXPECT_EQ(golden_bytes[129], 0xBF);  // ranges[63] low byte last
  EXPECT_TRUE(EncodesTo(full, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, full));
  EXPECT_EQ(to_json(full).at("ranges").size(), 64u);
  EXPECT_TRUE(SurvivesJson(full));
}

TEST(SonarGolden, RangeCountLargerThan64IsRejected) {
  Bytes bytes = three_ranges_bytes();
  bytes[0] = 0x00;
  bytes[1] = 65;  // range_count @0 = 65
  EXPECT_TRUE(Rejects<SonarData>(bytes, "ranges", 64, 65));
  bytes[0] = 0xFF;
  bytes[1] = 0xFF;  // 65535
  EXPECT_TRUE(Rejects<SonarData>(bytes, "ranges", 64, 65535));
}

TEST(SonarGolden, DataTruncatedOrOversizedIsRejected) {
  EXPECT_TRUE(Rejects<SonarData>(golden::drop_last(three_ranges_bytes()), "ranges", 130, 129));
  EXPECT_TRUE(Rejects<SonarData>(golden::kEmpty, "range_count", 130, 0));
  // Only the counted readings present is still too short: the 1.5 driver sends all 130 bytes.
  const Bytes full = three_ranges_bytes();
  EXPECT_TRUE(Rejects<SonarData>(Bytes(full.begin(), full.begin() + 8), "ranges", 130, 8));
  EXPECT_TRUE(Rejects<SonarData>(golden::with_extra_byte(three_ranges_bytes()), "", 130, 131));
}

SonarGeom two_poses() {
  SonarGeom g{.subtype = kSonarGetGeomReq, .pose_count = 2};
  g.poses[0] = {0x0102, ~0x0304, 0x0506};
  g.poses[1] = {~0x0708, 0x090A, ~0x0B0C};
  return g;
}

Bytes two_poses_bytes() {
  return WireBytes(387)
      .at(0, {0x01})                                  // subtype    @0 uint8 = PLAYER_SONAR_GET_GEOM_REQ (1)
      .at(1, {0x00, 0x02})                            // pose_count @1 uint16 = 2
      .at(3, {0x01, 0x02, 0xFC, 0xFB, 0x05, 0x06})    // poses[0]   @3 x, y = ~0x0304, yaw
      .at(9, {0xF8, 0xF7, 0x09, 0x0A, 0xF4, 0xF3})    // poses[1]   @9 x = ~0x0708, y, yaw = ~0x0B0C
      .zeros(15, 62 * 6)                              // poses[2..63] @15..386
      .done();
}

TEST(SonarGolden, GeometryReply) {
  EXPECT_TRUE(EncodesTo(two_poses(), two_poses_bytes()));
  EXPECT_TRUE(DecodesTo(two_poses_bytes(), two_poses()));
  const auto j = to_json(two_poses());
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "pose_count", "poses"}));
  EXPECT_EQ(j.at("poses"), (nlohmann::json{{0x0102, -0x0305, 0x0506}, {-0x0709, 0x090A, -0x0B0D}}));
  EXPECT_TRUE(SurvivesJson(two_poses()));
}

TEST(SonarGolden, GeometryCountAndLengthAreChecked) {
  Bytes bytes = two_poses_bytes();
  bytes[1] = 0x00;
  bytes[2] = 65;  // pose_count @1 = 65
  EXPECT_TRUE(Rejects<SonarGeom>(bytes, "poses", 64, 65));
  EXPECT_TRUE(Rejects<SonarGeom>(golden::drop_last(two_poses_bytes()), "poses", 387, 386));
  EXPECT_TRUE(Rejects<SonarGeom>(Bytes{0x01}, "pose_count", 387, 1));
  EXPECT_TRUE(Rejects<SonarGeom>(golden::with_extra_byte(two_poses_bytes()), "", 387, 388));
}

TEST(SonarGolden, PowerConfig) {
  const SonarPowerConfig value{.subtype = kSonarPowerReq, .value = 0x01};
  const Bytes golden_bytes{0x02,   // subtype @0 uint8 = PLAYER_SONAR_POWER_REQ (2)
                           0x01};  // value   @1 uint8
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(Rejects<SonarPowerConfig>(golden::drop_last(golden_bytes), "value", 2, 1));
  EXPECT_TRUE(Rejects<SonarPowerConfig>(golden::with_extra_byte(golden_bytes), "", 2, 3));
}

}  // namespace sonar_test
}  // namespace playerkit::protocol
