// Golden bytes are written from wire-format.md §5 "sonar" and "ir" by hand.
#include "interfaces/ranger_requests.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "interfaces/ranger_geometry.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::interfaces {
namespace ranger_requests_test {

using Bytes = std::vector<std::uint8_t>;

struct Ring final : RangerArray {
  std::optional<std::vector<geometry::Pose2>> sensor_poses() override { return poses; }
  bool set_power(bool on) override {
    powers.push_back(on);
    return accept_power;
  }
  std::optional<std::vector<geometry::Pose2>> poses =
      std::vector<geometry::Pose2>{{0.115, 0.130, std::numbers::pi / 2}, {-0.210, -0.025, -170 * std::numbers::pi / 180}};
  bool accept_power = true;
  std::vector<bool> powers;
};

core::Request request(Bytes payload) {
  core::Request r;
  r.payload = std::move(payload);
  return r;
}

TEST(SonarRequests, GeometryReplyHasTheTableLayout) {
  Ring ring;
  const core::RequestResult reply = answer_sonar_request(ring, request({1}));
  ASSERT_EQ(reply.type, protocol::MessageType::kAck);
  // subtype @0; pose_count uint16 @1; poses int16[64][3] @3, unused ones zero.
  Bytes golden(387, 0);
  const Bytes used = {0x01, 0x00, 0x02,
                      0x00, 0x73, 0x00, 0x82, 0x00, 0x5A,   // (115, 130, 90)
                      0xFF, 0x2E, 0xFF, 0xE7, 0xFF, 0x56};  // (-210, -25, -170)
  std::copy(used.begin(), used.end(), golden.begin());
  EXPECT_EQ(reply.payload, golden);
}

TEST(SonarRequests, PowerIsPassedOnAndAnsweredEmpty) {
  Ring ring;
  const core::RequestResult on = answer_sonar_request(ring, request({2, 1}));
  EXPECT_EQ(on.type, protocol::MessageType::kAck);
  EXPECT_TRUE(on.payload.empty());
  EXPECT_EQ(answer_sonar_request(ring, request({2, 0})).type, protocol::MessageType::kAck);
  ring.accept_power = false;
  EXPECT_EQ(answer_sonar_request(ring, request({2, 7})).type, protocol::MessageType::kNack);
  EXPECT_EQ(ring.powers, (std::vector<bool>{true, false, true}));
}

TEST(SonarRequests, WrongSizesUnknownSubtypesAndDeclinesAreNacked) {
  Ring ring;
  for (const Bytes& payload : {Bytes{}, Bytes{1, 0}, Bytes{2}, Bytes{2, 1, 0}, Bytes{3, 0}, Bytes{0}}) {
    EXPECT_EQ(answer_sonar_request(ring, request(payload)).type, protocol::MessageType::kNack)
        << ::testing::PrintToString(payload);
  }
  EXPECT_TRUE(ring.powers.empty());
  RangerArray nothing;
  EXPECT_EQ(answer_sonar_request(nothing, request({1})).type, protocol::MessageType::kNack);
  EXPECT_EQ(answer_sonar_request(nothing, request({2, 1})).type, protocol::MessageType::kNack);
}

TEST(SonarRequests, AtMost64TransducersAreReported) {
  const std::vector<geometry::Pose2> many(70, geometry::Pose2{0.001, 0.0, 0.0});
  const protocol::SonarGeom geom = sonar_geometry_reply(many);
  EXPECT_EQ(geom.pose_count, 64);
  EXPECT_EQ(geom.poses[63], (std::array<std::int16_t, 3>{1, 0, 0}));
  EXPECT_EQ(protocol::decode<protocol::SonarGeom>(protocol::encode(geom)), geom);
}

TEST(IrRequests, PoseReplyHasTheTableLayout) {
  Ring ring;
  ring.poses = std::vector<geometry::Pose2>{{0.031, -0.0004, std::numbers::pi / 4}};
  const core::RequestResult reply = answer_ir_request(ring, request({1}));
  ASSERT_EQ(reply.type, protocol::MessageType::kAck);
  // subtype @0; player_ir_pose_t @1: pose_count uint16 @1, poses int16[32][3] @3.
  Bytes golden(195, 0);
  const Bytes used = {0x01, 0x00, 0x01, 0x00, 0x1F, 0x00, 0x00, 0x00, 0x2D};  // (31, 0, 45)
  std::copy(used.begin(), used.end(), golden.begin());
  EXPECT_EQ(reply.payload, golden);
  const std::vector<geometry::Pose2> many(40, geometry::Pose2{});
  EXPECT_EQ(ir_pose_reply(many).poses.pose_count, 32);
}

TEST(IrRequests, PowerAndRefusals) {
  Ring ring;
  EXPECT_EQ(answer_ir_request(ring, request({2, 1})).type, protocol::MessageType::kAck);
  for (const Bytes& payload : {Bytes{1, 0}, Bytes{2}, Bytes{3, 1}}) {
    EXPECT_EQ(answer_ir_request(ring, request(payload)).type, protocol::MessageType::kNack)
        << ::testing::PrintToString(payload);
  }
  EXPECT_EQ(ring.powers, std::vector<bool>{true});
}

}  // namespace ranger_requests_test
}  // namespace playerkit::interfaces
