// Golden-byte tests of the `rwi` config struct (wire-format.md §5 "rwi").

#include "protocol/messages/rwi.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace rwi_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(RwiConfig::kWireSize == 2);  // player_rwi_config_t

TEST(RwiGolden, Config) {
  const RwiConfig value{.request = 0x33, .value = 0x44};
  const Bytes golden_bytes{0x33,   // request @0 uint8
                           0x44};  // value   @1 uint8
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"request", "value"}));
  EXPECT_EQ(j.at("value"), 0x44);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<RwiConfig>(golden::drop_last(golden_bytes), "value", 2, 1));
  EXPECT_TRUE(Rejects<RwiConfig>(golden::kEmpty, "request", 2, 0));
  EXPECT_TRUE(Rejects<RwiConfig>(golden::with_extra_byte(golden_bytes), "", 2, 3));
}

}  // namespace rwi_test
}  // namespace playerkit::protocol
