// Golden-byte tests of the `gripper` interface (wire-format.md §5 "gripper").

#include "protocol/messages/gripper.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace gripper_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(GripperData::kWireSize == 2);     // player_gripper_data_t
static_assert(GripperCommand::kWireSize == 2);  // player_gripper_cmd_t

TEST(GripperGolden, DataPacket) {
  const GripperData value{.state = 0x12, .beams = 0x34};
  const Bytes golden_bytes{0x12,   // state @0 uint8
                           0x34};  // beams @1 uint8
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"state", "beams"}));
  EXPECT_EQ(j.at("state"), 0x12);
  EXPECT_EQ(j.at("beams"), 0x34);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<GripperData>(golden::drop_last(golden_bytes), "beams", 2, 1));
  EXPECT_TRUE(Rejects<GripperData>(golden::kEmpty, "state", 2, 0));
  EXPECT_TRUE(Rejects<GripperData>(golden::with_extra_byte(golden_bytes), "", 2, 3));
}

TEST(GripperGolden, Command) {
  const GripperCommand value{.cmd = 0x56, .arg = 0x78};
  const Bytes golden_bytes{0x56,   // cmd @0 uint8
                           0x78};  // arg @1 uint8
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"cmd", "arg"}));
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<GripperCommand>(golden::drop_last(golden_bytes), "arg", 2, 1));
  EXPECT_TRUE(Rejects<GripperCommand>(golden::with_extra_byte(golden_bytes), "", 2, 3));
}

}  // namespace gripper_test
}  // namespace playerkit::protocol
