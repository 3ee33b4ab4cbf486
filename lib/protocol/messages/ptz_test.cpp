// Golden-byte tests of the `ptz` interface (wire-format.md §5 "ptz").

#include "protocol/messages/ptz.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace ptz_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(PtzData::kWireSize == 10);                 // player_ptz_data_t
static_assert(PtzCommand::kWireSize == 10);              // player_ptz_cmd_t
static_assert(PtzGenericConfig::kWireSize == 35);        // player_ptz_generic_config_t
static_assert(PtzVelocityModeConfig::kWireSize == 2);    // player_ptz_velocitymode_config_t

const PtzData kData{.pan = ~0x0102, .tilt = 0x0304, .zoom = 0x0506, .panspeed = ~0x0708, .tiltspeed = 0x090A};
const Bytes kDataBytes{0xFE, 0xFD,  // pan       @0 int16 = ~0x0102
                       0x03, 0x04,  // tilt      @2 int16
                       0x05, 0x06,  // zoom      @4 int16
                       0xF8, 0xF7,  // panspeed  @6 int16 = ~0x0708
                       0x09, 0x0A};  // tiltspeed @8 int16

TEST(PtzGolden, DataPacket) {
  ASSERT_EQ(kDataBytes.size(), 10u);
  EXPECT_TRUE(EncodesTo(kData, kDataBytes));
  EXPECT_TRUE(DecodesTo(kDataBytes, kData));
  const auto j = to_json(kData);
  EXPECT_TRUE(golden::HasFields(j, {"pan", "tilt", "zoom", "panspeed", "tiltspeed"}));
  EXPECT_EQ(j.at("pan"), -0x0103);
  EXPECT_EQ(j.at("tiltspeed"), 0x090A);
  EXPECT_TRUE(SurvivesJson(kData));
  EXPECT_TRUE(Rejects<PtzData>(golden::drop_last(kDataBytes), "tiltspeed", 10, 9));
  EXPECT_TRUE(Rejects<PtzData>(golden::kEmpty, "pan", 10, 0));
  EXPECT_TRUE(Rejects<PtzData>(golden::with_extra_byte(kDataBytes), "", 10, 11));
}

TEST(PtzGolden, Command) {
  const PtzCommand value{.pan = 0x1112, .tilt = ~0x2122, .zoom = 0x3132, .panspeed = 0x4142, .tiltspeed = ~0x5152};
  const Bytes golden_bytes{0x11, 0x12,  // pan       @0 int16
                           0xDE, 0xDD,  // tilt      @2 int16 = ~0x2122
                           0x31, 0x32,  // zoom      @4 int16
                           0x41, 0x42,  // panspeed  @6 int16
                           0xAE, 0xAD};  // tiltspeed @8 int16 = ~0x5152
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(Rejects<PtzCommand>(golden::drop_last(golden_bytes), "tiltspeed", 10, 9));
  EXPECT_TRUE(Rejects<PtzCommand>(golden::with_extra_byte(golden_bytes), "", 10, 11));
}

PtzGenericConfig four_config_bytes() {
  PtzGenericConfig c{.subtype = kPtzGenericConfigReq, .length = 4};
  c.config[0] = 0x81;
  c.config[1] = 0x01;
  c.config[2] = 0x06;
  c.config[3] = 0xFF;
  return c;
}

Bytes four_config_bytes_wire() {
  return WireBytes(35)
      .at(0, {0x01})                    // subtype   @0 uint8 = PLAYER_PTZ_GENERIC_CONFIG_REQ (1)
      .at(1, {0x00, 0x04})              // length    @1 uint16 = 4
      .at(3, {0x81, 0x01, 0x06, 0xFF})  // config[0..3] @3 uint8
      .zeros(7, 28)                     // config[4..31] @7..34
      .done();
}

TEST(PtzGolden, GenericConfig) {
  EXPECT_TRUE(EncodesTo(four_config_bytes(), four_config_bytes_wire()));
  EXPECT_TRUE(DecodesTo(four_config_bytes_wire(), four_config_bytes()));
  const auto j = to_json(four_config_bytes());
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "length", "config"}));
  EXPECT_EQ(j.at("length"), 4);
  EXPECT_EQ(j.at("config"), (nlohmann::json{0x81, 0x01, 0x06, 0xFF}));
  EXPECT_TRUE(SurvivesJson(four_config_bytes()));
  EXPECT_TRUE(Rejects<PtzGenericConfig>(golden::drop_last(four_config_bytes_wire()), "config", 35, 34));
  EXPECT_TRUE(Rejects<PtzGenericConfig>(golden::with_extra_byte(four_config_bytes_wire()), "", 35, 36));
}

TEST(PtzGolden, GenericConfigLengthLargerThan32IsRejected) {
  Bytes bytes = four_config_bytes_wire();
  bytes[1] = 0x00;
  bytes[2] = 33;  // length @1 = 33
  EXPECT_TRUE(Rejects<PtzGenericConfig>(bytes, "config", 32, 33));
  bytes[2] = 32;
  EXPECT_TRUE(golden::Accepts<PtzGenericConfig>(bytes));
}

TEST(PtzGolden, VelocityModeConfig) {
  const PtzVelocityModeConfig value{.subtype = kPtzControlModeReq, .mode = kPtzPositionControl};
  const Bytes golden_bytes{0x02,   // subtype @0 uint8 = PLAYER_PTZ_CONTROL_MODE_REQ (2)
                           0x01};  // mode    @1 uint8 = PLAYER_PTZ_POSITION_CONTROL (1)
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "mode"}));
  EXPECT_TRUE(Rejects<PtzVelocityModeConfig>(golden::drop_last(golden_bytes), "mode", 2, 1));
}

}  // namespace ptz_test
}  // namespace playerkit::protocol
