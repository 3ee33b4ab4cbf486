// Golden bytes are written from wire-format.md §5 "position" by hand, never
// by the encoder under test.
#include "interfaces/position_requests.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "protocol/binary_codec.hpp"

namespace playerkit::interfaces {
namespace position_requests_test {

using Bytes = std::vector<std::uint8_t>;

// A base that accepts everything and writes down what it was asked.
struct RecordingBase final : PositionBase {
  std::optional<BaseGeometry> geometry() override { return base_geometry; }
  bool set_motor_power(bool on) override { return record("power " + std::to_string(on)); }
  bool set_velocity_mode(std::uint8_t mode) override { return record("velocity mode " + std::to_string(mode)); }
  bool reset_odometry() override { return record("reset"); }
  bool set_odometry(const geometry::Pose2& pose) override {
    odometry = pose;
    return record("set odometry");
  }
  bool set_position_mode(bool on) override { return record("position mode " + std::to_string(on)); }
  bool set_speed_pid(const PidGains& g) override { return record(gains("speed pid", g)); }
  bool set_position_pid(const PidGains& g) override { return record(gains("position pid", g)); }
  bool set_speed_profile(const SpeedProfile& p) override {
    return record("profile " + std::to_string(p.speed) + " " + std::to_string(p.acceleration));
  }
  bool rmp_setting(std::uint8_t subtype, std::uint16_t value) override {
    return record("rmp " + std::to_string(subtype) + " " + std::to_string(value));
  }

  static std::string gains(const std::string& what, const PidGains& g) {
    return what + " " + std::to_string(g.kp) + " " + std::to_string(g.ki) + " " + std::to_string(g.kd);
  }
  bool record(const std::string& call) {
    calls.push_back(call);
    return accept;
  }

  std::optional<BaseGeometry> base_geometry = BaseGeometry{{-0.1, 0.0, 0.0}, 0.5, 0.45};
  bool accept = true;
  geometry::Pose2 odometry;
  std::vector<std::string> calls;
};

core::Request request(Bytes payload) {
  core::Request r;
  r.payload = std::move(payload);
  return r;
}

TEST(PositionRequests, GeometryReplyHasTheTableLayout) {
  RecordingBase base;
  base.base_geometry = BaseGeometry{{-0.1, 0.0203, std::numbers::pi / 2}, 0.5, 0.45};
  const core::RequestResult reply = answer_position_request(base, request({1}));
  ASSERT_EQ(reply.type, protocol::MessageType::kAck);
  // subtype @0; pose int16[3] @1 (x mm, y mm, yaw deg); size uint16[2] @7 (mm).
  const Bytes golden = {0x01, 0xFF, 0x9C, 0x00, 0x14, 0x00, 0x5A, 0x01, 0xF4, 0x01, 0xC2};
  EXPECT_EQ(reply.payload, golden);
}

TEST(PositionRequests, EveryRequestButGeometryIsAnsweredWithAnEmptyAck) {
  RecordingBase base;
  const std::vector<Bytes> requests = {
      {2, 1},                                   // MOTOR_POWER on
      {3, 7},                                   // VELOCITY_MODE 7
      {4},                                      // RESET_ODOM
      {5, 1},                                   // POSITION_MODE position
      {6, 0, 0, 0, 1, 0, 0, 0, 2, 0xFF, 0xFF, 0xFF, 0xFD},  // SPEED_PID 1 2 -3
      {7, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0},  // POSITION_PID 256 0 0
      {8, 0x01, 0x2C, 0x00, 0x64},              // SPEED_PROF 300 100
      {56, 0x00, 0x0F},                         // RMP_RST_INTEGRATORS all four
  };
  for (const Bytes& payload : requests) {
    const core::RequestResult reply = answer_position_request(base, request(payload));
    EXPECT_EQ(reply.type, protocol::MessageType::kAck) << int{payload[0]};
    EXPECT_TRUE(reply.payload.empty()) << int{payload[0]};
  }
  EXPECT_EQ(base.calls, (std::vector<std::string>{"power 1", "velocity mode 7", "reset", "position mode 1",
                                                  "speed pid 1 2 -3", "position pid 256 0 0", "profile 300 100",
                                                  "rmp 56 15"}));
}

TEST(PositionRequests, SetOdometryTakesMillimetresAndTheWholeTheta) {
  RecordingBase base;
  // x 1500 @1, y -250 @5, theta 270 @9: 1.5 read only theta's upper 16 bits.
  const Bytes payload = {9, 0x00, 0x00, 0x05, 0xDC, 0xFF, 0xFF, 0xFF, 0x06, 0x00, 0x00, 0x01, 0x0E};
  EXPECT_EQ(answer_position_request(base, request(payload)).type, protocol::MessageType::kAck);
  EXPECT_DOUBLE_EQ(base.odometry.x, 1.5);
  EXPECT_DOUBLE_EQ(base.odometry.y, -0.25);
  EXPECT_NEAR(base.odometry.yaw, -std::numbers::pi / 2, 1e-12);  // 270° is -90°
}

TEST(PositionRequests, WrongSizesAndUnknownSubtypesAreNackedWithoutAskingTheBase) {
  RecordingBase base;
  const std::vector<Bytes> refused = {
      {},               // no subtype
      {1, 0},           // GET_GEOM is the subtype alone
      {2},              // MOTOR_POWER short
      {3, 1, 1},        // VELOCITY_MODE long
      {4, 0},           // RESET_ODOM long
      {9, 0, 0, 0, 0},  // SET_ODOM short
      {6},              // SPEED_PID short
      {8, 0, 0, 0, 0, 0},
      {57, 0},          // RMP short
      {0}, {10}, {50}, {58}, {200},  // not position subtypes
  };
  for (const Bytes& payload : refused) {
    EXPECT_EQ(answer_position_request(base, request(payload)).type, protocol::MessageType::kNack)
        << ::testing::PrintToString(payload);
  }
  EXPECT_TRUE(base.calls.empty());
}

TEST(PositionRequests, TheDefaultBaseDeclinesEverything) {
  PositionBase nothing;
  for (const Bytes& payload : {Bytes{1}, Bytes{2, 1}, Bytes{3, 0}, Bytes{4}, Bytes{5, 0}, Bytes(13, 9)}) {
    EXPECT_EQ(answer_position_request(nothing, request(payload)).type, protocol::MessageType::kNack)
        << int{payload[0]};
  }
}

TEST(PositionRequests, ADecliningBaseGetsNack) {
  RecordingBase base;
  base.accept = false;
  base.base_geometry.reset();
  EXPECT_EQ(answer_position_request(base, request({1})).type, protocol::MessageType::kNack);
  EXPECT_EQ(answer_position_request(base, request({2, 1})).type, protocol::MessageType::kNack);
  EXPECT_EQ(base.calls, std::vector<std::string>{"power 1"});
}

TEST(PositionRequests, DecodedRequestsRoundTripThroughTheEncoder) {
  const protocol::PositionSetOdomRequest set{9, -1, 2, -3};
  const auto decoded = decode_position_request(protocol::encode(set));
  ASSERT_TRUE(decoded);
  EXPECT_EQ(std::get<protocol::PositionSetOdomRequest>(*decoded), set);
  const protocol::PositionSpeedProfRequest profile{8, -5, 6};
  EXPECT_EQ(std::get<protocol::PositionSpeedProfRequest>(*decode_position_request(protocol::encode(profile))),
            profile);
  EXPECT_EQ(std::get<GeometryQuery>(*decode_position_request(Bytes{1})), GeometryQuery{});
}

TEST(PositionRequests, GeometryIsRoundedAndClampedToItsFields) {
  const protocol::PositionGeom geom = position_geometry_reply({{0.0004, -40.0, -std::numbers::pi}, 70.0, -1.0});
  EXPECT_EQ(geom.subtype, protocol::kPositionGetGeomReq);
  EXPECT_EQ(geom.pose, (std::array<std::int16_t, 3>{0, -32768, -180}));
  EXPECT_EQ(geom.size, (std::array<std::uint16_t, 2>{65535, 0}));
  EXPECT_EQ(protocol::decode<protocol::PositionGeom>(protocol::encode(geom)), geom);
}

}  // namespace position_requests_test
}  // namespace playerkit::interfaces
