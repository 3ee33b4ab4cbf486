// Golden-byte tests of the `blinkenlight` interface (wire-format.md §5 "blinkenlight";
// player_blinkenlight_cmd_t is a typedef of the data struct).

#include "protocol/messages/blinkenlight.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace blinkenlight_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(BlinkenlightData::kWireSize == 3);  // player_blinkenlight_data_t

TEST(BlinkenlightGolden, DataPacket) {
  const BlinkenlightData value{.enable = 0x01, .period_ms = 0x0203};
  const Bytes golden_bytes{0x01,         // enable    @0 uint8
                           0x02, 0x03};  // period_ms @1 uint16
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"enable", "period_ms"}));
  EXPECT_EQ(j.at("period_ms"), 0x0203);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<BlinkenlightData>(golden::drop_last(golden_bytes), "period_ms", 3, 2));
  EXPECT_TRUE(Rejects<BlinkenlightData>(golden::kEmpty, "enable", 3, 0));
  EXPECT_TRUE(Rejects<BlinkenlightData>(golden::with_extra_byte(golden_bytes), "", 3, 4));
}

}  // namespace blinkenlight_test
}  // namespace playerkit::protocol
