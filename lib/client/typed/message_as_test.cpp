#include "client/typed/message_as.hpp"

#include <gtest/gtest.h>

#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"

namespace playerkit::client {
namespace message_as_test {

using protocol::MessageType;

protocol::Message message(MessageType type, std::uint16_t interface, std::vector<std::uint8_t> payload) {
  protocol::Message m;
  m.header = protocol::make_header(type, {interface, 1}, {}, {});
  m.payload = std::move(payload);
  m.header.size = static_cast<std::uint32_t>(m.payload.size());
  return m;
}

// player_position_data_t, written by hand from wire-format.md: xpos 1000, ypos -2 (big-endian
// two's complement), yaw 90, xspeed 0, yspeed 0, yawspeed 15, stall 1.
const std::vector<std::uint8_t> kPositionBytes{0x00, 0x00, 0x03, 0xE8, 0xFF, 0xFF, 0xFF, 0xFE, 0x00,
                                               0x00, 0x00, 0x5A, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
                                               0x00, 0x00, 0x00, 0x00, 0x00, 0x0F, 0x01};

std::string error_of(auto&& call) {
  try {
    call();
  } catch (const MessageKindError& e) {
    return e.what();
  }
  return "no MessageKindError";
}

TEST(TypedMessageAs, DataOfTheRightInterfaceDecodes) {
  const auto odom = data_as<protocol::PositionData>(message(MessageType::kData, protocol::kPositionCode, kPositionBytes));
  EXPECT_EQ(odom.xpos, 1000);
  EXPECT_EQ(odom.ypos, -2);
  EXPECT_EQ(odom.yaw, 90);
  EXPECT_EQ(odom.yawspeed, 15);
  EXPECT_EQ(odom.stall, 1);
}

TEST(TypedMessageAs, AnotherInterfaceIsRefusedByName) {
  const auto m = message(MessageType::kData, protocol::kPositionCode, kPositionBytes);
  EXPECT_EQ(error_of([&] { (void)data_as<protocol::LaserData>(m); }),
            "position:1: its data carries player_position_data_t, not player_laser_data_t (the data of laser)");
  // Refused for its interface, whatever its bytes would decode to.
  const auto dio = message(MessageType::kData, protocol::kDioCode, {1, 0, 0, 0, 1});
  EXPECT_THROW((void)data_as<protocol::PositionData>(dio), MessageKindError);
  const auto speech = message(MessageType::kData, protocol::kSpeechCode, {});
  EXPECT_EQ(error_of([&] { (void)data_as<protocol::PositionData>(speech); }),
            "speech:1: its data carries no known struct, not player_position_data_t (the data of position)");
}

TEST(TypedMessageAs, AnotherMessageTypeIsRefused) {
  const auto command = message(MessageType::kCommand, protocol::kPositionCode, kPositionBytes);
  EXPECT_EQ(error_of([&] { (void)data_as<protocol::PositionData>(command); }),
            "position:1: expected a data message carrying player_position_data_t, got a cmd message");
  const auto data = message(MessageType::kData, protocol::kPositionCode, kPositionBytes);
  EXPECT_THROW((void)command_as<protocol::PositionCommand>(data), MessageKindError);
}

TEST(TypedMessageAs, CommandsDecode) {
  protocol::PtzCommand wire;
  wire.pan = -45;
  wire.zoom = 60;
  const auto m = message(MessageType::kCommand, protocol::kPtzCode, protocol::encode(wire));
  EXPECT_EQ(command_as<protocol::PtzCommand>(m), wire);
  // The position3d command is not the position one.
  EXPECT_THROW((void)command_as<protocol::Position3dCommand>(m), MessageKindError);
}

TEST(TypedMessageAs, TruncatedPayloadsThrowDecodeError) {
  const std::vector<std::uint8_t> short_bytes(kPositionBytes.begin(), kPositionBytes.begin() + 10);
  EXPECT_THROW((void)data_as<protocol::PositionData>(message(MessageType::kData, protocol::kPositionCode, short_bytes)),
               protocol::DecodeError);
  // readlog's first, empty packet.
  EXPECT_THROW((void)data_as<protocol::LaserData>(message(MessageType::kData, protocol::kLaserCode, {})),
               protocol::DecodeError);
}

TEST(TypedMessageAs, RepliesDecodeAndRefusalsAreNamed) {
  protocol::LaserGeom geom;
  geom.subtype = protocol::kLaserGetGeom;
  geom.pose = {120, -5, 0};
  geom.size = {155, 185};
  const auto ack = message(MessageType::kAck, protocol::kLaserCode, protocol::encode(geom));
  EXPECT_EQ(reply_as<protocol::LaserGeom>(ack), geom);
  EXPECT_EQ(reply_as<protocol::LaserGeom>(ack, protocol::kLaserGetGeom), geom);

  EXPECT_EQ(error_of([&] { (void)reply_as<protocol::LaserGeom>(ack, protocol::kLaserGetConfig); }),
            "laser:1: the reply to get-config carries player_laser_config_t, not player_laser_geom_t");
  EXPECT_EQ(error_of([&] { (void)reply_as<protocol::PositionGeom>(ack); }),
            "laser:1: no request of laser is answered with player_position_geom_t");

  const auto nack = message(MessageType::kNack, protocol::kLaserCode, {});
  EXPECT_EQ(error_of([&] { (void)reply_as<protocol::LaserGeom>(nack); }),
            "laser:1: the request was refused (nack), there is no player_laser_geom_t to read");
  const auto err = message(MessageType::kError, protocol::kLaserCode, {});
  EXPECT_THROW((void)reply_as<protocol::LaserGeom>(err), MessageKindError);
  const auto data = message(MessageType::kData, protocol::kLaserCode, protocol::encode(geom));
  EXPECT_EQ(error_of([&] { (void)reply_as<protocol::LaserGeom>(data); }),
            "laser:1: expected an ack carrying player_laser_geom_t, got a data message");
}

TEST(TypedMessageAs, ARepliedStructSharedAcrossInterfacesIsAccepted) {
  // position3d's get-geom is answered with the 2-D geometry struct.
  protocol::PositionGeom geom;
  geom.subtype = protocol::kPosition3dGetGeomReq;
  geom.size = {500, 400};
  const auto ack = message(MessageType::kAck, protocol::kPosition3dCode, protocol::encode(geom));
  EXPECT_EQ(reply_as<protocol::PositionGeom>(ack), geom);
  // The power reply is power data without a subtype in front.
  const auto power = message(MessageType::kAck, protocol::kPowerCode, {0x00, 0x7D});
  EXPECT_EQ(reply_as<protocol::PowerData>(power, protocol::kMainPowerReq).charge, 125);
}

}  // namespace message_as_test
}  // namespace playerkit::client
