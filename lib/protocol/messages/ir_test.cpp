// Golden-byte tests of the `ir` interface (wire-format.md §5 "ir").

#include "protocol/messages/ir.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace ir_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(IrData::kWireSize == 130);         // player_ir_data_t
static_assert(IrPose::kWireSize == 194);         // player_ir_pose_t
static_assert(IrPoseRequest::kWireSize == 195);  // player_ir_pose_req_t
static_assert(IrPowerRequest::kWireSize == 2);   // player_ir_power_req_t

IrData two_samples() {
  IrData d{.range_count = 2};
  d.voltages[0] = 0x0102;
  d.voltages[1] = 0x0304;
  d.ranges[0] = 0x1112;
  d.ranges[1] = 0x1314;
  return d;
}

Bytes two_samples_bytes() {
  return WireBytes(130)
      .at(0, {0x00, 0x02})               // range_count @0 uint16 = 2
      .at(2, {0x01, 0x02, 0x03, 0x04})   // voltages[0..1] @2 uint16
      .zeros(6, 30 * 2)                  // voltages[2..31] @6..65
      .at(66, {0x11, 0x12, 0x13, 0x14})  // ranges[0..1] @66 uint16
      .zeros(70, 30 * 2)                 // ranges[2..31] @70..129
      .done();
}

TEST(IrGolden, DataPacket) {
  EXPECT_TRUE(EncodesTo(two_samples(), two_samples_bytes()));
  EXPECT_TRUE(DecodesTo(two_samples_bytes(), two_samples()));
  const auto j = to_json(two_samples());
  EXPECT_TRUE(golden::HasFields(j, {"range_count", "voltages", "ranges"}));
  EXPECT_EQ(j.at("voltages"), (nlohmann::json{0x0102, 0x0304}));
  EXPECT_EQ(j.at("ranges"), (nlohmann::json{0x1112, 0x1314}));
  EXPECT_TRUE(SurvivesJson(two_samples()));
}

TEST(IrGolden, DataCountAndLengthAreChecked) {
  Bytes bytes = two_samples_bytes();
  bytes[1] = 33;  // range_count @0 = 33 > PLAYER_IR_MAX_SAMPLES
  EXPECT_TRUE(Rejects<IrData>(bytes, "voltages", 32, 33));
  EXPECT_TRUE(Rejects<IrData>(golden::drop_last(two_samples_bytes()), "ranges", 130, 129));
  EXPECT_TRUE(Rejects<IrData>(Bytes(65, 0), "voltages", 130, 65));
  EXPECT_TRUE(Rejects<IrData>(golden::kEmpty, "range_count", 130, 0));
  EXPECT_TRUE(Rejects<IrData>(golden::with_extra_byte(two_samples_bytes()), "", 130, 131));
}

IrPose two_poses() {
  IrPose p{.pose_count = 2};
  p.poses[0] = {0x0102, ~0x0304, 0x0506};
  p.poses[1] = {~0x0708, 0x090A, 0x0B0C};
  return p;
}

// player_ir_pose_t at `at` (194 bytes): pose_count @+0, poses @+2 (6 bytes each).
void put_two_poses(WireBytes& w, std::size_t at) {
  w.at(at, {0x00, 0x02})                                  // pose_count = 2
      .at(at + 2, {0x01, 0x02, 0xFC, 0xFB, 0x05, 0x06})   // poses[0]: x, y = ~0x0304, yaw
      .at(at + 8, {0xF8, 0xF7, 0x09, 0x0A, 0x0B, 0x0C})   // poses[1]: x = ~0x0708, y, yaw
      .zeros(at + 14, 30 * 6);                            // poses[2..31]
}

TEST(IrGolden, Poses) {
  WireBytes w(194);
  put_two_poses(w, 0);
  const Bytes golden_bytes = w.done();
  EXPECT_TRUE(MatchesGolden(two_poses(), golden_bytes));
  const auto j = to_json(two_poses());
  EXPECT_TRUE(golden::HasFields(j, {"pose_count", "poses"}));
  EXPECT_EQ(j.at("poses"), (nlohmann::json{{0x0102, -0x0305, 0x0506}, {-0x0709, 0x090A, 0x0B0C}}));
  Bytes bad = golden_bytes;
  bad[1] = 33;  // pose_count @0 = 33
  EXPECT_TRUE(Rejects<IrPose>(bad, "poses", 32, 33));
  EXPECT_TRUE(Rejects<IrPose>(golden::drop_last(golden_bytes), "poses", 194, 193));
}

Bytes pose_request_bytes() {
  WireBytes w(195);
  w.at(0, {0x01});      // subtype @0 uint8 = PLAYER_IR_POSE_REQ (1)
  put_two_poses(w, 1);  // poses   @1 player_ir_pose_t: pose_count @1, poses @3
  return w.done();
}

TEST(IrGolden, PoseRequest) {
  const IrPoseRequest value{.subtype = kIrPoseReq, .poses = two_poses()};
  EXPECT_TRUE(MatchesGolden(value, pose_request_bytes()));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "poses"}));
  EXPECT_EQ(to_json(value).at("poses").at("pose_count"), 2);
  EXPECT_TRUE(Rejects<IrPoseRequest>(golden::drop_last(pose_request_bytes()), "poses", 195, 194));
  EXPECT_TRUE(Rejects<IrPoseRequest>(golden::with_extra_byte(pose_request_bytes()), "", 195, 196));
}

// The embedded pose_count counts poses[32] exactly as in a bare player_ir_pose_t
// (rejected above); embedding the struct must not lift the check.
TEST(IrGolden, PoseRequestWithPoseCountLargerThan32IsRejected) {
  Bytes bytes = pose_request_bytes();
  bytes[2] = 33;  // poses.pose_count @1 = 33
  EXPECT_THROW((void)decode<IrPoseRequest>(bytes), DecodeError);
}

TEST(IrGolden, PowerRequest) {
  const IrPowerRequest value{.subtype = kIrPowerReq, .state = 1};
  EXPECT_TRUE(MatchesGolden(value, Bytes{0x02,     // subtype @0 = PLAYER_IR_POWER_REQ (2)
                                         0x01}));  // state   @1
  EXPECT_TRUE(Rejects<IrPowerRequest>(Bytes{0x02}, "state", 2, 1));
}

}  // namespace ir_test
}  // namespace playerkit::protocol
