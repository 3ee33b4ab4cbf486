// Golden-byte tests of the `bumper` interface (wire-format.md §5 "bumper").

#include "protocol/messages/bumper.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace bumper_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(BumperData::kWireSize == 33);     // player_bumper_data_t
static_assert(BumperDefine::kWireSize == 10);   // player_bumper_define_t
static_assert(BumperGeom::kWireSize == 323);    // player_bumper_geom_t

BumperData five_bumpers() {
  BumperData d{.bumper_count = 5};
  for (std::size_t i = 0; i < 5; ++i) d.bumpers[i] = static_cast<std::uint8_t>(0xB1 + i);
  return d;
}

Bytes five_bumpers_bytes() {
  return WireBytes(33)
      .at(0, {0x05})                          // bumper_count @0 uint8 = 5
      .at(1, {0xB1, 0xB2, 0xB3, 0xB4, 0xB5})  // bumpers[0..4] @1 uint8
      .zeros(6, 27)                           // bumpers[5..31] @6..32
      .done();
}

TEST(BumperGolden, DataPacket) {
  EXPECT_TRUE(EncodesTo(five_bumpers(), five_bumpers_bytes()));
  EXPECT_TRUE(DecodesTo(five_bumpers_bytes(), five_bumpers()));
  const auto j = to_json(five_bumpers());
  EXPECT_TRUE(golden::HasFields(j, {"bumper_count", "bumpers"}));
  EXPECT_EQ(j.at("bumpers"), (nlohmann::json{0xB1, 0xB2, 0xB3, 0xB4, 0xB5}));
  EXPECT_TRUE(SurvivesJson(five_bumpers()));
}

TEST(BumperGolden, DataCountAndLengthAreChecked) {
  Bytes bytes = five_bumpers_bytes();
  bytes[0] = 33;  // bumper_count @0 = 33 > PLAYER_BUMPER_MAX_SAMPLES
  EXPECT_TRUE(Rejects<BumperData>(bytes, "bumpers", 32, 33));
  EXPECT_TRUE(Rejects<BumperData>(golden::drop_last(five_bumpers_bytes()), "bumpers", 33, 32));
  EXPECT_TRUE(Rejects<BumperData>(golden::kEmpty, "bumper_count", 33, 0));
  EXPECT_TRUE(Rejects<BumperData>(golden::with_extra_byte(five_bumpers_bytes()), "", 33, 34));
}

const BumperDefine kFront{.x_offset = ~0x0102, .y_offset = 0x0304, .th_offset = ~0x0506, .length = 0x0708, .radius = 0x090A};
const BumperDefine kRear{.x_offset = 0x1112, .y_offset = ~0x1314, .th_offset = 0x1516, .length = 0x1718, .radius = 0x191A};

TEST(BumperGolden, Definition) {
  const Bytes golden_bytes{0xFE, 0xFD,   // x_offset  @0 int16 = ~0x0102
                           0x03, 0x04,   // y_offset  @2 int16
                           0xFA, 0xF9,   // th_offset @4 int16 = ~0x0506
                           0x07, 0x08,   // length    @6 uint16
                           0x09, 0x0A};  // radius    @8 uint16
  EXPECT_TRUE(MatchesGolden(kFront, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(kFront), {"x_offset", "y_offset", "th_offset", "length", "radius"}));
}

BumperGeom two_definitions() {
  BumperGeom g{.subtype = kBumperGetGeomReq, .bumper_count = 2};
  g.bumper_def[0] = kFront;
  g.bumper_def[1] = kRear;
  return g;
}

Bytes two_definitions_bytes() {
  return WireBytes(323)
      .at(0, {0x01})                                                      // subtype      @0 uint8 = 1
      .at(1, {0x00, 0x02})                                                // bumper_count @1 uint16 = 2
      .at(3, {0xFE, 0xFD, 0x03, 0x04, 0xFA, 0xF9, 0x07, 0x08, 0x09, 0x0A})  // bumper_def[0] @3
      .at(13, {0x11, 0x12, 0xEC, 0xEB, 0x15, 0x16, 0x17, 0x18, 0x19, 0x1A})  // bumper_def[1] @13, y = ~0x1314
      .zeros(23, 30 * 10)                                                 // bumper_def[2..31] @23..322
      .done();
}

TEST(BumperGolden, GeometryReply) {
  EXPECT_TRUE(EncodesTo(two_definitions(), two_definitions_bytes()));
  EXPECT_TRUE(DecodesTo(two_definitions_bytes(), two_definitions()));
  const auto j = to_json(two_definitions());
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "bumper_count", "bumper_def"}));
  ASSERT_EQ(j.at("bumper_def").size(), 2u);
  EXPECT_EQ(j.at("bumper_def")[1].at("y_offset"), -0x1315);
  EXPECT_TRUE(SurvivesJson(two_definitions()));
}

TEST(BumperGolden, GeometryCountAndLengthAreChecked) {
  Bytes bytes = two_definitions_bytes();
  bytes[2] = 33;  // bumper_count @1 = 33
  EXPECT_TRUE(Rejects<BumperGeom>(bytes, "bumper_def", 32, 33));
  EXPECT_TRUE(Rejects<BumperGeom>(golden::drop_last(two_definitions_bytes()), "bumper_def", 323, 322));
  EXPECT_TRUE(Rejects<BumperGeom>(golden::with_extra_byte(two_definitions_bytes()), "", 323, 324));
}

}  // namespace bumper_test
}  // namespace playerkit::protocol
