// Golden-byte tests of the `rflex` config struct (wire-format.md §5 "rflex").

#include "protocol/messages/rflex.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace rflex_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(RflexConfig::kWireSize == 2);  // player_rflex_config_t

TEST(RflexGolden, Config) {
  const RflexConfig value{.request = 0x11, .value = 0x22};
  const Bytes golden_bytes{0x11,   // request @0 uint8
                           0x22};  // value   @1 uint8
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"request", "value"}));
  EXPECT_EQ(j.at("request"), 0x11);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<RflexConfig>(golden::drop_last(golden_bytes), "value", 2, 1));
  EXPECT_TRUE(Rejects<RflexConfig>(golden::kEmpty, "request", 2, 0));
  EXPECT_TRUE(Rejects<RflexConfig>(golden::with_extra_byte(golden_bytes), "", 2, 3));
}

}  // namespace rflex_test
}  // namespace playerkit::protocol
