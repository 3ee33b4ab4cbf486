// Golden-byte tests of the `position` interface (wire-format.md §5 "position", §7).

#include "protocol/messages/position.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace position_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(PositionData::kWireSize == 25);                 // player_position_data_t
static_assert(PositionCommand::kWireSize == 26);              // player_position_cmd_t
static_assert(PositionGeom::kWireSize == 11);                 // player_position_geom_t
static_assert(PositionPowerConfig::kWireSize == 2);           // player_position_power_config_t
static_assert(PositionVelocityModeConfig::kWireSize == 2);    // player_position_velocitymode_config_t
static_assert(PositionResetOdomConfig::kWireSize == 1);       // player_position_resetodom_config_t
static_assert(PositionPositionModeRequest::kWireSize == 2);   // player_position_position_mode_req_t
static_assert(PositionSetOdomRequest::kWireSize == 13);       // player_position_set_odom_req_t
static_assert(PositionSpeedPidRequest::kWireSize == 13);      // player_position_speed_pid_req_t
static_assert(PositionPositionPidRequest::kWireSize == 13);   // player_position_position_pid_req_t
static_assert(PositionSpeedProfRequest::kWireSize == 5);      // player_position_speed_prof_req_t
static_assert(RmpConfig::kWireSize == 3);                     // player_rmp_config_t

const PositionData kData{.xpos = 0x01020304,
                         .ypos = ~0x11121314,  // -0x11121315
                         .yaw = ~0x21222324,
                         .xspeed = 0x31323334,
                         .yspeed = ~0x41424344,
                         .yawspeed = 0x51525354,
                         .stall = 0x61};

const Bytes kDataBytes{0x01, 0x02, 0x03, 0x04,  // xpos     @0  int32
                       0xEE, 0xED, 0xEC, 0xEB,  // ypos     @4  int32 = ~0x11121314
                       0xDE, 0xDD, 0xDC, 0xDB,  // yaw      @8  int32 = ~0x21222324
                       0x31, 0x32, 0x33, 0x34,  // xspeed   @12 int32
                       0xBE, 0xBD, 0xBC, 0xBB,  // yspeed   @16 int32 = ~0x41424344
                       0x51, 0x52, 0x53, 0x54,  // yawspeed @20 int32
                       0x61};                   // stall    @24 uint8

TEST(PositionGolden, DataPacket) {
  ASSERT_EQ(kDataBytes.size(), 25u);
  EXPECT_TRUE(EncodesTo(kData, kDataBytes));
  EXPECT_TRUE(DecodesTo(kDataBytes, kData));
  EXPECT_EQ(decode<PositionData>(kDataBytes).ypos, -0x11121315);
}

TEST(PositionGolden, DataJson) {
  const auto j = to_json(kData);
  EXPECT_TRUE(golden::HasFields(j, {"xpos", "ypos", "yaw", "xspeed", "yspeed", "yawspeed", "stall"}));
  EXPECT_EQ(j.at("xpos"), 0x01020304);
  EXPECT_EQ(j.at("ypos"), -0x11121315);
  EXPECT_EQ(j.at("stall"), 0x61);
  EXPECT_TRUE(SurvivesJson(kData));
}

TEST(PositionGolden, DataTruncatedOrOversizedIsRejected) {
  EXPECT_TRUE(Rejects<PositionData>(golden::drop_last(kDataBytes), "stall", 25, 24));
  EXPECT_TRUE(Rejects<PositionData>(golden::kEmpty, "xpos", 25, 0));
  EXPECT_TRUE(Rejects<PositionData>(Bytes(kDataBytes.begin(), kDataBytes.begin() + 10), "yaw", 25, 10));
  EXPECT_TRUE(Rejects<PositionData>(golden::with_extra_byte(kDataBytes), "", 25, 26));
}

TEST(PositionGolden, Command) {
  const PositionCommand value{.xpos = ~0x01020304,
                              .ypos = 0x11121314,
                              .yaw = ~0x21222324,
                              .xspeed = 0x31323334,
                              .yspeed = ~0x41424344,
                              .yawspeed = 0x51525354,
                              .state = 0x61,
                              .type = 0x01};
  const Bytes golden_bytes{0xFE, 0xFD, 0xFC, 0xFB,  // xpos     @0  int32 = ~0x01020304
                           0x11, 0x12, 0x13, 0x14,  // ypos     @4  int32
                           0xDE, 0xDD, 0xDC, 0xDB,  // yaw      @8  int32 = ~0x21222324
                           0x31, 0x32, 0x33, 0x34,  // xspeed   @12 int32
                           0xBE, 0xBD, 0xBC, 0xBB,  // yspeed   @16 int32 = ~0x41424344
                           0x51, 0x52, 0x53, 0x54,  // yawspeed @20 int32
                           0x61,                    // state    @24 uint8
                           0x01};                   // type     @25 uint8 = position command
  ASSERT_EQ(golden_bytes.size(), 26u);
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"xpos", "ypos", "yaw", "xspeed", "yspeed", "yawspeed", "state", "type"}));
  EXPECT_EQ(j.at("xpos"), -0x01020305);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<PositionCommand>(golden::drop_last(golden_bytes), "type", 26, 25));
  EXPECT_TRUE(Rejects<PositionCommand>(golden::with_extra_byte(golden_bytes), "", 26, 27));
}

// §7: pose is declared uint16 but carries signed offsets and yaw; playerkit reads int16.
TEST(PositionGolden, GeometryPoseIsSigned) {
  const PositionGeom value{.subtype = kPositionGetGeomReq,
                           .pose = {~0x0102, 0x0304, ~0x0506},
                           .size = {0x0708, 0x090A}};
  const Bytes golden_bytes{0x01,        // subtype @0 uint8 = PLAYER_POSITION_GET_GEOM_REQ (1)
                           0xFE, 0xFD,  // pose[0] @1 x   = ~0x0102 = -259 mm
                           0x03, 0x04,  // pose[1] @3 y
                           0xFA, 0xF9,  // pose[2] @5 yaw = ~0x0506
                           0x07, 0x08,  // size[0] @7 uint16 length
                           0x09, 0x0A};  // size[1] @9 uint16 width
  ASSERT_EQ(golden_bytes.size(), 11u);
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const PositionGeom decoded = decode<PositionGeom>(golden_bytes);
  EXPECT_EQ(decoded.pose[0], -259);
  EXPECT_EQ(decoded.pose[2], -0x0507);
  const auto j = to_json(value);
  EXPECT_EQ(j.at("pose"), (nlohmann::json{-259, 0x0304, -0x0507}));
  EXPECT_EQ(j.at("size"), (nlohmann::json{0x0708, 0x090A}));
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<PositionGeom>(golden::drop_last(golden_bytes), "size", 11, 10));
  EXPECT_TRUE(Rejects<PositionGeom>(Bytes{0x01, 0xFE}, "pose", 11, 2));
  EXPECT_TRUE(Rejects<PositionGeom>(golden::with_extra_byte(golden_bytes), "", 11, 12));
}

TEST(PositionGolden, SmallConfigRequests) {
  EXPECT_TRUE(MatchesGolden(PositionPowerConfig{.request = kPositionMotorPowerReq, .value = 1},
                            Bytes{0x02,     // request @0 = PLAYER_POSITION_MOTOR_POWER_REQ (2)
                                  0x01}));  // value   @1
  EXPECT_TRUE(MatchesGolden(PositionVelocityModeConfig{.request = kPositionVelocityModeReq, .value = 0x7E},
                            Bytes{0x03,     // request @0 = PLAYER_POSITION_VELOCITY_MODE_REQ (3)
                                  0x7E}));  // value   @1
  EXPECT_TRUE(MatchesGolden(PositionResetOdomConfig{.request = kPositionResetOdomReq},
                            Bytes{0x04}));  // request @0 = PLAYER_POSITION_RESET_ODOM_REQ (4)
  EXPECT_TRUE(MatchesGolden(PositionPositionModeRequest{.subtype = kPositionPositionModeReq, .state = 1},
                            Bytes{0x05,     // subtype @0 = PLAYER_POSITION_POSITION_MODE_REQ (5)
                                  0x01}));  // state   @1
  EXPECT_TRUE(Rejects<PositionPowerConfig>(Bytes{0x02}, "value", 2, 1));
  EXPECT_TRUE(Rejects<PositionResetOdomConfig>(golden::kEmpty, "request", 1, 0));
  EXPECT_TRUE(Rejects<PositionResetOdomConfig>(Bytes{0x04, 0x00}, "", 1, 2));
}

TEST(PositionGolden, SetOdometryRequest) {
  const PositionSetOdomRequest value{.subtype = kPositionSetOdomReq,
                                     .x = 0x01020304,
                                     .y = ~0x11121314,
                                     .theta = 0x21222324};
  const Bytes golden_bytes{0x09,                    // subtype @0 uint8 = PLAYER_POSITION_SET_ODOM_REQ (9)
                           0x01, 0x02, 0x03, 0x04,  // x       @1 int32
                           0xEE, 0xED, 0xEC, 0xEB,  // y       @5 int32 = ~0x11121314
                           0x21, 0x22, 0x23, 0x24};  // theta  @9 int32
  ASSERT_EQ(golden_bytes.size(), 13u);
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "x", "y", "theta"}));
  EXPECT_TRUE(Rejects<PositionSetOdomRequest>(golden::drop_last(golden_bytes), "theta", 13, 12));
  EXPECT_TRUE(Rejects<PositionSetOdomRequest>(golden::with_extra_byte(golden_bytes), "", 13, 14));
}

TEST(PositionGolden, PidRequests) {
  const PositionSpeedPidRequest speed{.subtype = kPositionSpeedPidReq,
                                      .kp = 0x01020304,
                                      .ki = ~0x11121314,
                                      .kd = 0x21222324};
  const Bytes speed_bytes{0x06,                    // subtype @0 = PLAYER_POSITION_SPEED_PID_REQ (6)
                          0x01, 0x02, 0x03, 0x04,  // kp @1 int32
                          0xEE, 0xED, 0xEC, 0xEB,  // ki @5 int32 = ~0x11121314
                          0x21, 0x22, 0x23, 0x24};  // kd @9 int32
  EXPECT_TRUE(MatchesGolden(speed, speed_bytes));

  const PositionPositionPidRequest position{.subtype = kPositionPositionPidReq,
                                            .kp = ~0x01020304,
                                            .ki = 0x11121314,
                                            .kd = ~0x21222324};
  const Bytes position_bytes{0x07,                    // subtype @0 = PLAYER_POSITION_POSITION_PID_REQ (7)
                             0xFE, 0xFD, 0xFC, 0xFB,  // kp @1 int32 = ~0x01020304
                             0x11, 0x12, 0x13, 0x14,  // ki @5 int32
                             0xDE, 0xDD, 0xDC, 0xDB};  // kd @9 int32 = ~0x21222324
  EXPECT_TRUE(MatchesGolden(position, position_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(position), {"subtype", "kp", "ki", "kd"}));
  EXPECT_TRUE(Rejects<PositionPositionPidRequest>(golden::drop_last(position_bytes), "kd", 13, 12));
}

TEST(PositionGolden, SpeedProfileRequest) {
  const PositionSpeedProfRequest value{.subtype = kPositionSpeedProfReq, .speed = 0x0102, .acc = ~0x0304};
  const Bytes golden_bytes{0x08,        // subtype @0 uint8 = PLAYER_POSITION_SPEED_PROF_REQ (8)
                           0x01, 0x02,  // speed   @1 int16
                           0xFC, 0xFB};  // acc    @3 int16 = ~0x0304
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_EQ(to_json(value).at("acc"), -0x0305);
  EXPECT_TRUE(Rejects<PositionSpeedProfRequest>(golden::drop_last(golden_bytes), "acc", 5, 4));
}

TEST(PositionGolden, RmpConfig) {
  const RmpConfig value{.subtype = kPositionRmpRstIntegrators,
                        .value = kPositionRmpRstIntLeft | kPositionRmpRstIntForeaft | 0x0100};
  const Bytes golden_bytes{0x38,        // subtype @0 uint8  = PLAYER_POSITION_RMP_RST_INTEGRATORS (56)
                           0x01, 0x0A};  // value  @1 uint16 = 0x0100 | LEFT (2) | FOREAFT (8)
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "value"}));
  EXPECT_TRUE(Rejects<RmpConfig>(golden::drop_last(golden_bytes), "value", 3, 2));
  EXPECT_TRUE(Rejects<RmpConfig>(golden::with_extra_byte(golden_bytes), "", 3, 4));
}

}  // namespace position_test
}  // namespace playerkit::protocol
