#include "families/nomad/protocol/nclient_message.hpp"

#include <gtest/gtest.h>

#include "families/nomad/protocol/nomad_requests.hpp"

namespace playerkit::hardware::nomad {
namespace nclient_message_test {

using Bytes = std::vector<std::uint8_t>;

// nomad.md §1.1: type and word count big-endian, then 4-byte big-endian words.
TEST(NclientMessage, VelocityModeGoesOutBigEndianWithFourByteWords) {
  EXPECT_EQ(encode(velocity(394, -150, 0)),
            (Bytes{0x00, 0x0C, 0x00, 0x03, 0x00, 0x00, 0x01, 0x8A, 0xFF, 0xFF, 0xFF, 0x6A, 0x00, 0x00, 0x00, 0x00}));
}

TEST(NclientMessage, SetupRequestsHaveTheSheetsWords) {
  EXPECT_EQ(encode(connect_robot(0x1234)), (Bytes{0x00, 0x66, 0x00, 0x02, 0, 0, 0, 1, 0, 0, 0x12, 0x34}));
  EXPECT_EQ(sensor_mask().type, 16);
  EXPECT_EQ(sensor_mask().words, (std::vector<std::int32_t>{0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x0E, 0x00}));
  EXPECT_EQ(encode(command_timeout(5)), (Bytes{0x00, 0x1A, 0x00, 0x01, 0, 0, 0, 5}));
  EXPECT_EQ(encode(zero()), (Bytes{0x00, 0x14, 0x00, 0x00}));
  EXPECT_EQ(encode(get_state()), (Bytes{0x00, 0x0F, 0x00, 0x00}));
  EXPECT_EQ(accelerations(kSetupAccelerations).words, (std::vector<std::int32_t>{300, 300, 300}));
  EXPECT_EQ(accelerations(kSetupAccelerations).type, 10);
  EXPECT_EQ(speeds(kSetupSpeeds).words, (std::vector<std::int32_t>{200, 450, 450}));
  EXPECT_EQ(speeds(kSetupSpeeds).type, 11);
}

TEST(NclientMessage, DecodeUndoesEncode) {
  const Message message{message_type::kVelocityMode, {-1, 0x7FFFFFFF, -0x7FFFFFFF - 1}};
  EXPECT_EQ(decode(encode(message)), message);
  EXPECT_FALSE(decode(Bytes{0x00, 0x0F, 0x00, 0x01, 0, 0}).has_value());
  EXPECT_FALSE(decode(Bytes{0x00}).has_value());
}

TEST(NclientFormat, CutsAtTheWordCountWhateverTheReadSizes) {
  const NclientFormat format;
  const Bytes two = encode(velocity(1, 2, 3));
  EXPECT_EQ(format.scan(std::span(two).first(2)).kind, framing::FrameScan::Kind::need_more);
  EXPECT_EQ(format.scan(std::span(two).first(7)).length, two.size());
  const auto whole = format.scan(two);
  EXPECT_EQ(whole.kind, framing::FrameScan::Kind::frame);
  EXPECT_EQ(whole.length, two.size());
}

TEST(NclientFormat, AnAbsurdCountIsNoise) {
  const NclientFormat format;
  const auto scan = format.scan(Bytes{0x00, 0x50, 0xFF, 0xFF, 0, 0, 0, 0});
  EXPECT_EQ(scan.kind, framing::FrameScan::Kind::skip);
  EXPECT_EQ(scan.length, 1U);
}

TEST(NclientFormat, AReaderExpectingStatesSkipsStrayBytesToTheNextState) {
  const NclientFormat format(state_reply_types());
  Bytes stream{0x01, 0x02, 0x00};
  const Bytes state = encode(state_reply({}));
  stream.insert(stream.end(), state.begin(), state.end());
  std::size_t skipped = 0;
  std::span<const std::uint8_t> rest(stream);
  for (auto scan = format.scan(rest); scan.kind == framing::FrameScan::Kind::skip; scan = format.scan(rest)) {
    skipped += scan.length;
    rest = rest.subspan(scan.length);
  }
  EXPECT_EQ(skipped, 3U);
  EXPECT_EQ(format.scan(rest).length, state.size());
  EXPECT_EQ(NclientFormat().scan(Bytes{0x01, 0x02, 0x00, 0x00}).kind, framing::FrameScan::Kind::frame);
}

TEST(NomadState, TheSheetsWordsInTheirPlaces) {
  RobotState state;
  state.simulation_speed = 1;
  state.ir[15] = 30;
  state.sonar[0] = 255;
  state.sonar[15] = 12;
  state.bumpers = 0x5;
  state.x = 100;
  state.y = -200;
  state.steering = 900;
  state.turret = 450;
  state.translation_velocity = 40;
  state.steering_velocity = 150;
  state.turret_velocity = -150;
  state.motor_status = 3;
  state.compass = 1800;
  state.controller_time = 77;
  state.cpu_voltage = 120;
  state.motor_voltage = 130;
  const Message reply = state_reply(state);
  ASSERT_EQ(reply.type, 80);
  ASSERT_EQ(reply.words.size(), kStateWords);
  EXPECT_EQ(reply.words[16], 30);
  EXPECT_EQ(reply.words[17], 255);
  EXPECT_EQ(reply.words[32], 12);
  EXPECT_EQ(reply.words[33], 5);
  EXPECT_EQ(reply.words[34], 100);
  EXPECT_EQ(reply.words[35], -200);
  EXPECT_EQ(reply.words[36], 900);
  EXPECT_EQ(reply.words[37], 450);
  EXPECT_EQ(reply.words[38], 40);
  EXPECT_EQ(reply.words[39], 150);
  EXPECT_EQ(reply.words[40], -150);
  EXPECT_EQ(reply.words[43], 1800);
  EXPECT_EQ(reply.words[45], 0);
  EXPECT_EQ(reply.words[46], 77);
  EXPECT_EQ(reply.words[48], 130);
  EXPECT_EQ(parse_state(reply), state);
}

TEST(NomadState, LaserPointsShiftTheTail) {
  RobotState state;
  state.laser_points = {1, 2, 3, 4};
  state.controller_time = 9;
  const Message reply = state_reply(state);
  EXPECT_EQ(reply.words.size(), kStateWords + 4);
  EXPECT_EQ(reply.words[45], 2);
  EXPECT_EQ(parse_state(reply), state);
}

TEST(NomadState, ShortWrongOrFailedRepliesAreNotStates) {
  Message reply = state_reply({});
  reply.words.pop_back();
  EXPECT_FALSE(parse_state(reply).has_value());
  Message bad_count = state_reply({});
  bad_count.words[45] = 3;
  EXPECT_FALSE(parse_state(bad_count).has_value());
  EXPECT_FALSE(parse_state({message_type::kError, std::vector<std::int32_t>(49)}).has_value());
  EXPECT_TRUE(is_failure({message_type::kError, {4}}));
  EXPECT_TRUE(is_failure({-1, {}}));
  EXPECT_FALSE(is_failure({message_type::kConnectRobot, {7020}}));
}

}  // namespace nclient_message_test
}  // namespace playerkit::hardware::nomad
