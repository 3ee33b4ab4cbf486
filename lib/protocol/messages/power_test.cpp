// Golden-byte tests of the `power` interface (wire-format.md §5 "power").

#include "protocol/messages/power.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace power_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(PowerData::kWireSize == 2);    // player_power_data_t
static_assert(PowerConfig::kWireSize == 1);  // player_power_config_t

TEST(PowerGolden, DataPacket) {
  const PowerData value{.charge = 0x0102};
  const Bytes golden_bytes{0x01, 0x02};  // charge @0 uint16, decivolts
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"charge"}));
  EXPECT_EQ(j.at("charge"), 0x0102);
  EXPECT_TRUE(SurvivesJson(value));
}

TEST(PowerGolden, DataTruncatedOrOversizedIsRejected) {
  EXPECT_TRUE(Rejects<PowerData>(Bytes{0x01}, "charge", 2, 1));
  EXPECT_TRUE(Rejects<PowerData>(golden::kEmpty, "charge", 2, 0));
  EXPECT_TRUE(Rejects<PowerData>(Bytes{0x01, 0x02, 0x03}, "", 2, 3));
}

TEST(PowerGolden, ConfigRequest) {
  const PowerConfig value{.subtype = kMainPowerReq};
  const Bytes golden_bytes{0x0E};  // subtype @0 uint8 = PLAYER_MAIN_POWER_REQ (14)
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_EQ(to_json(value).at("subtype"), 14);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<PowerConfig>(golden::kEmpty, "subtype", 1, 0));
  EXPECT_TRUE(Rejects<PowerConfig>(Bytes{0x0E, 0x00}, "", 1, 2));
}

}  // namespace power_test
}  // namespace playerkit::protocol
