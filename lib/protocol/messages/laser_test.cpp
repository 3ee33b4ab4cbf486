// Golden-byte tests of the `laser` interface (wire-format.md §5 "laser", §6).

#include "protocol/messages/laser.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace laser_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(LaserData::kWireSize == 1213);       // player_laser_data_t
static_assert(LaserGeom::kWireSize == 11);         // player_laser_geom_t
static_assert(LaserConfig::kWireSize == 10);       // player_laser_config_t
static_assert(LaserPowerConfig::kWireSize == 2);   // player_laser_power_config_t

LaserData three_beams() {
  LaserData d{.min_angle = ~0x0102, .max_angle = 0x0304, .resolution = 0x0506, .range_res = 0x0708, .range_count = 3};
  d.ranges[0] = 0x1112;
  d.ranges[1] = 0x2122;
  d.ranges[2] = 0x3132;
  d.intensity[0] = 0x41;
  d.intensity[1] = 0x42;
  d.intensity[2] = 0x43;
  return d;
}

Bytes three_beams_bytes() {
  return WireBytes(1213)
      .at(0, {0xFE, 0xFD})          // min_angle   @0  int16 = ~0x0102 = -259
      .at(2, {0x03, 0x04})          // max_angle   @2  int16
      .at(4, {0x05, 0x06})          // resolution  @4  uint16
      .at(6, {0x07, 0x08})          // range_res   @6  uint16
      .at(8, {0x00, 0x03})          // range_count @8  uint16 = 3
      .at(10, {0x11, 0x12})         // ranges[0]   @10 uint16
      .at(12, {0x21, 0x22})         // ranges[1]   @12
      .at(14, {0x31, 0x32})         // ranges[2]   @14
      .zeros(16, 398 * 2)           // ranges[3..400] @16..811
      .at(812, {0x41, 0x42, 0x43})  // intensity[0..2] @812 uint8
      .zeros(815, 398)              // intensity[3..400] @815..1212
      .done();
}

TEST(LaserGolden, DataPacketIsAlwaysTheFull1213Bytes) {
  EXPECT_TRUE(EncodesTo(three_beams(), three_beams_bytes()));
  EXPECT_TRUE(DecodesTo(three_beams_bytes(), three_beams()));
}

TEST(LaserGolden, DataPacketWithAll401Beams) {
  LaserData scan{.min_angle = -9000, .max_angle = 9000, .resolution = 50, .range_res = 1, .range_count = 401};
  WireBytes wire(1213);
  wire.at(0, {0xDC, 0xD8})   // min_angle   @0 = -9000 (0x10000 - 0x2328)
      .at(2, {0x23, 0x28})   // max_angle   @2 = 9000
      .at(4, {0x00, 0x32})   // resolution  @4 = 50
      .at(6, {0x00, 0x01})   // range_res   @6 = 1
      .at(8, {0x01, 0x91});  // range_count @8 = 401
  for (std::size_t i = 0; i < 401; ++i) {
    scan.ranges[i] = static_cast<std::uint16_t>(0x1000 + i);  // ranges[i] @10+2i = 0x10|i>>8, i&0xFF
    wire.at(10 + 2 * i, {static_cast<std::uint8_t>(0x10 | (i >> 8)), static_cast<std::uint8_t>(i & 0xFF)});
    scan.intensity[i] = static_cast<std::uint8_t>(0xFF - (i & 0xFF));  // intensity[i] @812+i
    wire.at(812 + i, {static_cast<std::uint8_t>(0xFF - (i & 0xFF))});
  }
  const Bytes golden_bytes = wire.done();
  EXPECT_EQ(golden_bytes[10], 0x10);    // ranges[0] = 0x1000, high byte first
  EXPECT_EQ(golden_bytes[811], 0x90);   // ranges[400] = 0x1190, low byte
  EXPECT_EQ(golden_bytes[812], 0xFF);   // intensity[0]
  EXPECT_EQ(golden_bytes[1212], 0x6F);  // intensity[400] = 0xFF - 0x90
  EXPECT_TRUE(EncodesTo(scan, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, scan));
  EXPECT_TRUE(SurvivesJson(scan));
  EXPECT_EQ(to_json(scan).at("ranges").size(), 401u);
}

TEST(LaserGolden, DataJsonShowsOnlyTheCountedBeams) {
  const auto j = to_json(three_beams());
  EXPECT_TRUE(golden::HasFields(j, {"min_angle", "max_angle", "resolution", "range_res", "range_count", "ranges",
                                    "intensity"}));
  EXPECT_EQ(j.at("min_angle"), -259);
  EXPECT_EQ(j.at("range_count"), 3);
  EXPECT_EQ(j.at("ranges"), (nlohmann::json{0x1112, 0x2122, 0x3132}));
  EXPECT_EQ(j.at("intensity"), (nlohmann::json{0x41, 0x42, 0x43}));
  EXPECT_TRUE(SurvivesJson(three_beams()));

  // Beams past range_count are not in the JSON, so they come back as zero.
  LaserData stale = three_beams();
  stale.ranges[3] = 0x7777;
  stale.intensity[400] = 0x77;
  EXPECT_EQ(to_json(stale), j);
  EXPECT_EQ(from_json<LaserData>(to_json(stale)), three_beams());
}

TEST(LaserGolden, DataTruncatedOrOversizedIsRejected) {
  const Bytes bytes = three_beams_bytes();
  EXPECT_TRUE(Rejects<LaserData>(golden::drop_last(bytes), "intensity", 1213, 1212));
  try {
    (void)decode<LaserData>(golden::drop_last(bytes));
    ADD_FAILURE() << "a 1212-byte laser payload was accepted";
  } catch (const DecodeError& e) {
    EXPECT_STREQ(e.what(), "player_laser_data_t: payload truncated in field 'intensity': expected 1213 bytes, got 1212");
  }
  EXPECT_TRUE(Rejects<LaserData>(golden::kEmpty, "min_angle", 1213, 0));
  EXPECT_TRUE(Rejects<LaserData>(Bytes(bytes.begin(), bytes.begin() + 500), "ranges", 1213, 500));
  EXPECT_TRUE(Rejects<LaserData>(Bytes(bytes.begin(), bytes.begin() + 9), "range_count", 1213, 9));
  EXPECT_TRUE(Rejects<LaserData>(golden::with_extra_byte(bytes), "", 1213, 1214));
}

TEST(LaserGolden, RangeCountLargerThan401IsRejected) {
  Bytes bytes = three_beams_bytes();
  bytes[8] = 0x01;
  bytes[9] = 0x92;  // range_count @8 = 402
  EXPECT_TRUE(Rejects<LaserData>(bytes, "ranges", 401, 402));
  bytes[9] = 0x91;  // 401 fits
  EXPECT_TRUE(golden::Accepts<LaserData>(bytes));
}

// The encoder should not produce a payload its own decoder rejects: a scan that
// claims 402 beams cannot be put on the wire.
TEST(LaserGolden, EncodeRejectsRangeCountLargerThan401) {
  LaserData bad = three_beams();
  bad.range_count = 402;
  EXPECT_THROW((void)encode(bad), EncodeError);
}

TEST(LaserGolden, Geometry) {
  const LaserGeom value{.subtype = kLaserGetGeom, .pose = {~0x0102, 0x0304, ~0x0506}, .size = {0x0708, ~0x090A}};
  const Bytes golden_bytes{0x01,        // subtype @0 uint8 = PLAYER_LASER_GET_GEOM (1)
                           0xFE, 0xFD,  // pose[0] @1 int16 x = ~0x0102
                           0x03, 0x04,  // pose[1] @3 int16 y
                           0xFA, 0xF9,  // pose[2] @5 int16 yaw = ~0x0506
                           0x07, 0x08,  // size[0] @7 int16
                           0xF6, 0xF5};  // size[1] @9 int16 = ~0x090A
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "pose", "size"}));
  EXPECT_EQ(j.at("pose"), (nlohmann::json{-0x0103, 0x0304, -0x0507}));
  EXPECT_TRUE(Rejects<LaserGeom>(golden::drop_last(golden_bytes), "size", 11, 10));
  EXPECT_TRUE(Rejects<LaserGeom>(golden::with_extra_byte(golden_bytes), "", 11, 12));
}

TEST(LaserGolden, ConfigRequest) {
  const LaserConfig value{.subtype = kLaserSetConfig,
                          .min_angle = ~0x1112,
                          .max_angle = 0x2122,
                          .resolution = 0x3132,
                          .range_res = 0x4142,
                          .intensity = 0x51};
  const Bytes golden_bytes{0x02,        // subtype    @0 uint8 = PLAYER_LASER_SET_CONFIG (2)
                           0xEE, 0xED,  // min_angle  @1 int16 = ~0x1112
                           0x21, 0x22,  // max_angle  @3 int16
                           0x31, 0x32,  // resolution @5 uint16
                           0x41, 0x42,  // range_res  @7 uint16
                           0x51};       // intensity  @9 uint8
  ASSERT_EQ(golden_bytes.size(), 10u);
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "min_angle", "max_angle", "resolution", "range_res", "intensity"}));
  EXPECT_EQ(j.at("min_angle"), -0x1113);
  EXPECT_TRUE(Rejects<LaserConfig>(golden::drop_last(golden_bytes), "intensity", 10, 9));
  EXPECT_TRUE(Rejects<LaserConfig>(golden::kEmpty, "subtype", 10, 0));
  EXPECT_TRUE(Rejects<LaserConfig>(golden::with_extra_byte(golden_bytes), "", 10, 11));
}

TEST(LaserGolden, PowerConfig) {
  const LaserPowerConfig value{.subtype = kLaserPowerConfig, .value = 1};
  const Bytes golden_bytes{0x04,   // subtype @0 uint8 = PLAYER_LASER_POWER_CONFIG (4)
                           0x01};  // value   @1 uint8
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(Rejects<LaserPowerConfig>(golden::drop_last(golden_bytes), "value", 2, 1));
}

}  // namespace laser_test
}  // namespace playerkit::protocol
