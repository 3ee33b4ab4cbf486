// Golden-byte tests of the `gps` interface (wire-format.md §5 "gps").

#include "protocol/messages/gps.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace gps_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(GpsData::kWireSize == 40);  // player_gps_data_t

const GpsData kData{.time_sec = 0x01020304,
                    .time_usec = 0x05060708,
                    .latitude = 0x090A0B0C,
                    .longitude = ~0x11121314,
                    .altitude = ~0x15161718,
                    .utm_e = 0x191A1B1C,
                    .utm_n = 0x21222324,
                    .quality = 0x02,
                    .num_sats = 0x29,
                    .hdop = 0x3132,
                    .err_horz = 0x41424344,
                    .err_vert = 0x51525354};
const Bytes kDataBytes{0x01, 0x02, 0x03, 0x04,  // time_sec  @0  uint32
                       0x05, 0x06, 0x07, 0x08,  // time_usec @4  uint32
                       0x09, 0x0A, 0x0B, 0x0C,  // latitude  @8  int32
                       0xEE, 0xED, 0xEC, 0xEB,  // longitude @12 int32 = ~0x11121314 (west)
                       0xEA, 0xE9, 0xE8, 0xE7,  // altitude  @16 int32 = ~0x15161718
                       0x19, 0x1A, 0x1B, 0x1C,  // utm_e     @20 int32
                       0x21, 0x22, 0x23, 0x24,  // utm_n     @24 int32
                       0x02,                    // quality   @28 uint8 = DGPS fix
                       0x29,                    // num_sats  @29 uint8
                       0x31, 0x32,              // hdop      @30 uint16
                       0x41, 0x42, 0x43, 0x44,  // err_horz  @32 uint32
                       0x51, 0x52, 0x53, 0x54};  // err_vert @36 uint32

TEST(GpsGolden, DataPacket) {
  ASSERT_EQ(kDataBytes.size(), 40u);
  EXPECT_TRUE(EncodesTo(kData, kDataBytes));
  EXPECT_TRUE(DecodesTo(kDataBytes, kData));
}

TEST(GpsGolden, DataJson) {
  const auto j = to_json(kData);
  EXPECT_TRUE(golden::HasFields(j, {"time_sec", "time_usec", "latitude", "longitude", "altitude", "utm_e", "utm_n",
                                    "quality", "num_sats", "hdop", "err_horz", "err_vert"}));
  EXPECT_EQ(j.at("longitude"), -0x11121315);
  EXPECT_EQ(j.at("hdop"), 0x3132);
  EXPECT_EQ(j.at("err_vert"), 0x51525354);
  EXPECT_TRUE(SurvivesJson(kData));
}

TEST(GpsGolden, TruncatedOrOversizedIsRejected) {
  EXPECT_TRUE(Rejects<GpsData>(golden::drop_last(kDataBytes), "err_vert", 40, 39));
  EXPECT_TRUE(Rejects<GpsData>(golden::kEmpty, "time_sec", 40, 0));
  EXPECT_TRUE(Rejects<GpsData>(Bytes(kDataBytes.begin(), kDataBytes.begin() + 31), "hdop", 40, 31));
  EXPECT_TRUE(Rejects<GpsData>(golden::with_extra_byte(kDataBytes), "", 40, 41));
}

}  // namespace gps_test
}  // namespace playerkit::protocol
