// Golden-byte tests of the `position3d` interface (wire-format.md §5 "position3d", §7).

#include "protocol/messages/position3d.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace position3d_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(Position3dData::kWireSize == 49);        // player_position3d_data_t
static_assert(Position3dCommand::kWireSize == 48);     // player_position3d_cmd_t
static_assert(Position3dPowerConfig::kWireSize == 2);  // player_position3d_power_config_t

const Position3dData kData{.xpos = 0x01020304,
                           .ypos = ~0x05060708,
                           .zpos = 0x090A0B0C,
                           .roll = ~0x11121314,
                           .pitch = 0x15161718,
                           .yaw = ~0x191A1B1C,
                           .xspeed = 0x21222324,
                           .yspeed = ~0x25262728,
                           .zspeed = 0x292A2B2C,
                           .rollspeed = ~0x31323334,
                           .pitchspeed = 0x35363738,
                           .yawspeed = ~0x393A3B3C,
                           .stall = 0x41};

Bytes data_bytes() {
  return WireBytes(49)
      .at(0, {0x01, 0x02, 0x03, 0x04})   // xpos       @0  int32
      .at(4, {0xFA, 0xF9, 0xF8, 0xF7})   // ypos       @4  int32 = ~0x05060708
      .at(8, {0x09, 0x0A, 0x0B, 0x0C})   // zpos       @8  int32
      .at(12, {0xEE, 0xED, 0xEC, 0xEB})  // roll       @12 int32 = ~0x11121314
      .at(16, {0x15, 0x16, 0x17, 0x18})  // pitch      @16 int32
      .at(20, {0xE6, 0xE5, 0xE4, 0xE3})  // yaw        @20 int32 = ~0x191A1B1C
      .at(24, {0x21, 0x22, 0x23, 0x24})  // xspeed     @24 int32
      .at(28, {0xDA, 0xD9, 0xD8, 0xD7})  // yspeed     @28 int32 = ~0x25262728
      .at(32, {0x29, 0x2A, 0x2B, 0x2C})  // zspeed     @32 int32
      .at(36, {0xCE, 0xCD, 0xCC, 0xCB})  // rollspeed  @36 int32 = ~0x31323334
      .at(40, {0x35, 0x36, 0x37, 0x38})  // pitchspeed @40 int32
      .at(44, {0xC6, 0xC5, 0xC4, 0xC3})  // yawspeed   @44 int32 = ~0x393A3B3C
      .at(48, {0x41})                    // stall      @48 uint8
      .done();
}

TEST(Position3dGolden, DataPacket) {
  EXPECT_TRUE(EncodesTo(kData, data_bytes()));
  EXPECT_TRUE(DecodesTo(data_bytes(), kData));
  const auto j = to_json(kData);
  EXPECT_TRUE(golden::HasFields(j, {"xpos", "ypos", "zpos", "roll", "pitch", "yaw", "xspeed", "yspeed",
                                    "zspeed", "rollspeed", "pitchspeed", "yawspeed", "stall"}));
  EXPECT_EQ(j.at("yaw"), -0x191A1B1D);
  EXPECT_EQ(j.at("pitchspeed"), 0x35363738);
  EXPECT_TRUE(SurvivesJson(kData));
}

TEST(Position3dGolden, DataTruncatedOrOversizedIsRejected) {
  EXPECT_TRUE(Rejects<Position3dData>(golden::drop_last(data_bytes()), "stall", 49, 48));
  EXPECT_TRUE(Rejects<Position3dData>(golden::kEmpty, "xpos", 49, 0));
  EXPECT_TRUE(Rejects<Position3dData>(golden::with_extra_byte(data_bytes()), "", 49, 50));
}

const Position3dCommand kCommand{.xpos = ~0x01020304,
                                 .ypos = 0x05060708,
                                 .zpos = ~0x090A0B0C,
                                 .roll = ~0x11121314,
                                 .pitch = ~0x15161718,
                                 .yaw = ~0x191A1B1C,
                                 .xspeed = 0x21222324,
                                 .yspeed = ~0x25262728,
                                 .zspeed = 0x292A2B2C,
                                 .rollspeed = ~0x31323334,
                                 .pitchspeed = 0x35363738,
                                 .yawspeed = ~0x393A3B3C};

Bytes command_bytes() {
  return WireBytes(48)
      .at(0, {0xFE, 0xFD, 0xFC, 0xFB})   // xpos       @0  int32 = ~0x01020304
      .at(4, {0x05, 0x06, 0x07, 0x08})   // ypos       @4  int32
      .at(8, {0xF6, 0xF5, 0xF4, 0xF3})   // zpos       @8  int32 = ~0x090A0B0C
      .at(12, {0xEE, 0xED, 0xEC, 0xEB})  // roll       @12 declared uint32, read int32 = ~0x11121314
      .at(16, {0xEA, 0xE9, 0xE8, 0xE7})  // pitch      @16 declared uint32, read int32 = ~0x15161718
      .at(20, {0xE6, 0xE5, 0xE4, 0xE3})  // yaw        @20 declared uint32, read int32 = ~0x191A1B1C
      .at(24, {0x21, 0x22, 0x23, 0x24})  // xspeed     @24 int32
      .at(28, {0xDA, 0xD9, 0xD8, 0xD7})  // yspeed     @28 int32 = ~0x25262728
      .at(32, {0x29, 0x2A, 0x2B, 0x2C})  // zspeed     @32 int32
      .at(36, {0xCE, 0xCD, 0xCC, 0xCB})  // rollspeed  @36 int32 = ~0x31323334
      .at(40, {0x35, 0x36, 0x37, 0x38})  // pitchspeed @40 int32
      .at(44, {0xC6, 0xC5, 0xC4, 0xC3})  // yawspeed   @44 int32 = ~0x393A3B3C
      .done();
}

TEST(Position3dGolden, Command) {
  EXPECT_TRUE(EncodesTo(kCommand, command_bytes()));
  EXPECT_TRUE(DecodesTo(command_bytes(), kCommand));
  EXPECT_TRUE(SurvivesJson(kCommand));
  EXPECT_TRUE(Rejects<Position3dCommand>(golden::drop_last(command_bytes()), "yawspeed", 48, 47));
  EXPECT_TRUE(Rejects<Position3dCommand>(golden::with_extra_byte(command_bytes()), "", 48, 49));
}

// §7: roll/pitch/yaw of the command are declared uint32, but they are the same
// signed angles as in the data packet, so playerkit reads them as int32.
TEST(Position3dGolden, CommandAnglesAreSigned) {
  const Position3dCommand decoded = decode<Position3dCommand>(command_bytes());
  EXPECT_EQ(decoded.roll, -0x11121315);
  EXPECT_EQ(decoded.pitch, -0x15161719);
  EXPECT_EQ(decoded.yaw, -0x191A1B1D);
  const auto j = to_json(decoded);
  EXPECT_EQ(j.at("roll"), -0x11121315);
  EXPECT_EQ(j.at("yaw"), -0x191A1B1D);

  Bytes minus_one_arcsec = command_bytes();
  for (std::size_t i = 20; i < 24; ++i) minus_one_arcsec[i] = 0xFF;  // yaw @20 = FF FF FF FF
  EXPECT_EQ(decode<Position3dCommand>(minus_one_arcsec).yaw, -1);
}

TEST(Position3dGolden, PowerConfig) {
  const Position3dPowerConfig value{.request = kPosition3dMotorPowerReq, .value = 1};
  const Bytes golden_bytes{0x02,   // request @0 uint8 = PLAYER_POSITION3D_MOTOR_POWER_REQ (2)
                           0x01};  // value   @1 uint8
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"request", "value"}));
  EXPECT_TRUE(Rejects<Position3dPowerConfig>(golden::drop_last(golden_bytes), "value", 2, 1));
  EXPECT_TRUE(Rejects<Position3dPowerConfig>(golden::with_extra_byte(golden_bytes), "", 2, 3));
}

}  // namespace position3d_test
}  // namespace playerkit::protocol
