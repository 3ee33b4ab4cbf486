// Golden-byte tests of the `bps` structs (wire-format.md §5 "bps"; no interface code).

#include "protocol/messages/bps.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace bps_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(BpsData::kWireSize == 28);    // player_bps_data_t
static_assert(BpsConfig::kWireSize == 1);   // player_bps_config_t
static_assert(BpsBeacon::kWireSize == 26);  // player_bps_beacon_t

TEST(BpsGolden, DataPacket) {
  const BpsData value{.px = 0x01020304,
                      .py = ~0x05060708,
                      .pa = 0x090A0B0C,
                      .ux = 0x11121314,
                      .uy = 0x15161718,
                      .ua = 0x191A1B1C,
                      .err = ~0x21222324};
  const Bytes golden_bytes{0x01, 0x02, 0x03, 0x04,   // px  @0  int32
                           0xFA, 0xF9, 0xF8, 0xF7,   // py  @4  int32 = ~0x05060708
                           0x09, 0x0A, 0x0B, 0x0C,   // pa  @8  int32
                           0x11, 0x12, 0x13, 0x14,   // ux  @12 int32
                           0x15, 0x16, 0x17, 0x18,   // uy  @16 int32
                           0x19, 0x1A, 0x1B, 0x1C,   // ua  @20 int32
                           0xDE, 0xDD, 0xDC, 0xDB};  // err @24 int32 = ~0x21222324
  ASSERT_EQ(golden_bytes.size(), 28u);
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"px", "py", "pa", "ux", "uy", "ua", "err"}));
  EXPECT_EQ(j.at("err"), -0x21222325);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<BpsData>(golden::drop_last(golden_bytes), "err", 28, 27));
  EXPECT_TRUE(Rejects<BpsData>(golden::kEmpty, "px", 28, 0));
  EXPECT_TRUE(Rejects<BpsData>(golden::with_extra_byte(golden_bytes), "", 28, 29));
}

TEST(BpsGolden, ConfigRequest) {
  EXPECT_TRUE(MatchesGolden(BpsConfig{.subtype = kBpsGetConfig}, Bytes{0x02}));  // subtype @0 = PLAYER_BPS_GET_CONFIG
  EXPECT_TRUE(Rejects<BpsConfig>(golden::kEmpty, "subtype", 1, 0));
  EXPECT_TRUE(Rejects<BpsConfig>(Bytes{0x02, 0x00}, "", 1, 2));
}

TEST(BpsGolden, BeaconRequest) {
  const BpsBeacon value{.subtype = kBpsSetBeacon,
                        .id = 0x07,
                        .px = ~0x01020304,
                        .py = 0x05060708,
                        .pa = ~0x090A0B0C,
                        .ux = 0x11121314,
                        .uy = 0x15161718,
                        .ua = 0x191A1B1C};
  const Bytes golden_bytes{0x03,                     // subtype @0  uint8 = PLAYER_BPS_SET_BEACON (3)
                           0x07,                     // id      @1  uint8
                           0xFE, 0xFD, 0xFC, 0xFB,   // px      @2  int32 = ~0x01020304
                           0x05, 0x06, 0x07, 0x08,   // py      @6  int32
                           0xF6, 0xF5, 0xF4, 0xF3,   // pa      @10 int32 = ~0x090A0B0C
                           0x11, 0x12, 0x13, 0x14,   // ux      @14 int32
                           0x15, 0x16, 0x17, 0x18,   // uy      @18 int32
                           0x19, 0x1A, 0x1B, 0x1C};  // ua      @22 int32
  ASSERT_EQ(golden_bytes.size(), 26u);
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "id", "px", "py", "pa", "ux", "uy", "ua"}));
  EXPECT_TRUE(Rejects<BpsBeacon>(golden::drop_last(golden_bytes), "ua", 26, 25));
  EXPECT_TRUE(Rejects<BpsBeacon>(golden::with_extra_byte(golden_bytes), "", 26, 27));
}

}  // namespace bps_test
}  // namespace playerkit::protocol
