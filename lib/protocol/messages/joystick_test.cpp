// Golden-byte tests of the `joystick` struct (wire-format.md §5 "joystick"; no interface code).

#include "protocol/messages/joystick.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace joystick_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(JoystickData::kWireSize == 4);  // player_joystick_data_t

TEST(JoystickGolden, DataPacket) {
  const JoystickData value{.xpos = 0x81, .ypos = 0x7F, .button0 = 0x01, .button1 = 0x02};
  const Bytes golden_bytes{0x81,   // xpos    @0 uint8
                           0x7F,   // ypos    @1 uint8
                           0x01,   // button0 @2 uint8
                           0x02};  // button1 @3 uint8
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"xpos", "ypos", "button0", "button1"}));
  EXPECT_EQ(j.at("xpos"), 0x81);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<JoystickData>(golden::drop_last(golden_bytes), "button1", 4, 3));
  EXPECT_TRUE(Rejects<JoystickData>(golden::kEmpty, "xpos", 4, 0));
  EXPECT_TRUE(Rejects<JoystickData>(golden::with_extra_byte(golden_bytes), "", 4, 5));
}

}  // namespace joystick_test
}  // namespace playerkit::protocol
