// Golden-byte tests of the `descartes` interface (wire-format.md §5 "descartes").

#include "protocol/messages/descartes.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace descartes_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(DescartesConfig::kWireSize == 6);   // player_descartes_config_t
static_assert(DescartesData::kWireSize == 12);    // player_descartes_data_t

TEST(DescartesGolden, DataPacket) {
  const DescartesData value{.xpos = ~0x01020304, .ypos = 0x05060708, .theta = ~0x090A, .bumpers = {0x0B, 0x0C}};
  const Bytes golden_bytes{0xFE, 0xFD, 0xFC, 0xFB,  // xpos    @0  int32 = ~0x01020304
                           0x05, 0x06, 0x07, 0x08,  // ypos    @4  int32
                           0xF6, 0xF5,              // theta   @8  int16 = ~0x090A
                           0x0B, 0x0C};             // bumpers @10 uint8[2]
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"xpos", "ypos", "theta", "bumpers"}));
  EXPECT_EQ(j.at("theta"), -0x090B);
  EXPECT_EQ(j.at("bumpers"), (nlohmann::json{0x0B, 0x0C}));
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<DescartesData>(golden::drop_last(golden_bytes), "bumpers", 12, 11));
  EXPECT_TRUE(Rejects<DescartesData>(golden::kEmpty, "xpos", 12, 0));
  EXPECT_TRUE(Rejects<DescartesData>(golden::with_extra_byte(golden_bytes), "", 12, 13));
}

TEST(DescartesGolden, Config) {
  const DescartesConfig value{.speed = 0x0102, .heading = ~0x0304, .distance = 0x0506};
  const Bytes golden_bytes{0x01, 0x02,   // speed    @0 int16
                           0xFC, 0xFB,   // heading  @2 int16 = ~0x0304
                           0x05, 0x06};  // distance @4 int16
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"speed", "heading", "distance"}));
  EXPECT_TRUE(Rejects<DescartesConfig>(golden::drop_last(golden_bytes), "distance", 6, 5));
  EXPECT_TRUE(Rejects<DescartesConfig>(golden::with_extra_byte(golden_bytes), "", 6, 7));
}

}  // namespace descartes_test
}  // namespace playerkit::protocol
