// Golden-byte tests of the `truth` interface (wire-format.md §5 "truth").

#include "protocol/messages/truth.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace truth_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(TruthData::kWireSize == 12);        // player_truth_data_t
static_assert(TruthPose::kWireSize == 13);        // player_truth_pose_t
static_assert(TruthFiducialId::kWireSize == 3);   // player_truth_fiducial_id_t

TEST(TruthGolden, DataPacket) {
  const TruthData value{.px = 0x01020304, .py = ~0x05060708, .pa = 0x090A0B0C};
  const Bytes golden_bytes{0x01, 0x02, 0x03, 0x04,   // px @0 int32
                           0xFA, 0xF9, 0xF8, 0xF7,   // py @4 int32 = ~0x05060708
                           0x09, 0x0A, 0x0B, 0x0C};  // pa @8 int32
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"px", "py", "pa"}));
  EXPECT_EQ(j.at("py"), -0x05060709);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<TruthData>(golden::drop_last(golden_bytes), "pa", 12, 11));
  EXPECT_TRUE(Rejects<TruthData>(golden::kEmpty, "px", 12, 0));
  EXPECT_TRUE(Rejects<TruthData>(golden::with_extra_byte(golden_bytes), "", 12, 13));
}

TEST(TruthGolden, PoseRequest) {
  const TruthPose value{.subtype = kTruthSetPose, .px = ~0x01020304, .py = 0x05060708, .pa = ~0x090A0B0C};
  const Bytes golden_bytes{0x01,                     // subtype @0 uint8 = PLAYER_TRUTH_SET_POSE (1)
                           0xFE, 0xFD, 0xFC, 0xFB,   // px      @1 int32 = ~0x01020304
                           0x05, 0x06, 0x07, 0x08,   // py      @5 int32
                           0xF6, 0xF5, 0xF4, 0xF3};  // pa      @9 int32 = ~0x090A0B0C
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "px", "py", "pa"}));
  EXPECT_TRUE(Rejects<TruthPose>(golden::drop_last(golden_bytes), "pa", 13, 12));
  EXPECT_TRUE(Rejects<TruthPose>(golden::with_extra_byte(golden_bytes), "", 13, 14));
}

TEST(TruthGolden, FiducialIdRequest) {
  const TruthFiducialId value{.subtype = kTruthSetFiducialId, .id = ~0x0102};
  const Bytes golden_bytes{0x04,         // subtype @0 uint8 = PLAYER_TRUTH_SET_FIDUCIAL_ID (4)
                           0xFE, 0xFD};  // id      @1 int16 = ~0x0102
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_EQ(to_json(value).at("id"), -0x0103);
  EXPECT_TRUE(Rejects<TruthFiducialId>(golden::drop_last(golden_bytes), "id", 3, 2));
}

}  // namespace truth_test
}  // namespace playerkit::protocol
