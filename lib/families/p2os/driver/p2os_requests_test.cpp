// Every request of every p2os device: the ones the sheet lists are answered
// (wrong sizes NACKed), every other one NACKed.
#include <gtest/gtest.h>

#include "families/p2os/driver/p2os_test_support.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers {
namespace p2os_requests_test {

using namespace p2os_testing;
using Bytes = std::vector<std::uint8_t>;

struct Fixture : ::testing::Test {
  void SetUp() override {
    for (core::Device* device : devices.builtin.devices.all()) ASSERT_TRUE(device->subscribe()) << device->name();
  }
  EmulatedRobot robot;
  RobotDevices devices{robot.port(), std::string(kEveryDevice)};
};

using P2osRequests = Fixture;

TEST_F(P2osRequests, PositionAnswersItsFiveRequests) {
  core::Device& position = devices.position();
  auto reply = ask(position, Bytes{protocol::kPositionGetGeomReq});
  ASSERT_TRUE(acked(reply));
  const auto geometry = protocol::decode<protocol::PositionGeom>(reply->payload);
  EXPECT_EQ(geometry.subtype, protocol::kPositionGetGeomReq);
  EXPECT_EQ(geometry.pose, (std::array<std::int16_t, 3>{-100, 0, 0}));
  EXPECT_EQ(geometry.size, (std::array<std::uint16_t, 2>{500, 450}));

  EXPECT_TRUE(acked(ask(position, protocol::PositionPowerConfig{2, 1})));
  EXPECT_TRUE(eventually([&] { return robot.motors_enabled(); }));
  EXPECT_TRUE(acked(ask(position, protocol::PositionVelocityModeConfig{3, 0})));
  EXPECT_TRUE(acked(ask(position, Bytes{protocol::kPositionResetOdomReq})));
  EXPECT_TRUE(acked(ask(position, protocol::PositionSetOdomRequest{9, 1, 2, 3})));
  // Replies to position requests carry no payload but GET_GEOM's.
  EXPECT_TRUE(ask(position, protocol::PositionPowerConfig{2, 0})->payload.empty());
}

TEST_F(P2osRequests, PositionNacksWrongSizesAndEverythingElse) {
  core::Device& position = devices.position();
  EXPECT_TRUE(nacked(ask(position, Bytes{protocol::kPositionGetGeomReq, 0})));
  EXPECT_TRUE(nacked(ask(position, Bytes{protocol::kPositionMotorPowerReq})));
  EXPECT_TRUE(nacked(ask(position, Bytes{protocol::kPositionVelocityModeReq, 1, 1})));
  EXPECT_TRUE(nacked(ask(position, Bytes{protocol::kPositionResetOdomReq, 0})));
  EXPECT_TRUE(nacked(ask(position, Bytes{protocol::kPositionSetOdomReq, 0, 0, 0, 0})));
  for (const std::uint8_t other : {protocol::kPositionPositionModeReq, protocol::kPositionSpeedPidReq,
                                   protocol::kPositionPositionPidReq, protocol::kPositionSpeedProfReq,
                                   protocol::kPositionRmpVelocityScale, std::uint8_t{0}, std::uint8_t{200}}) {
    EXPECT_TRUE(nacked(ask(position, Bytes(13, other)))) << int{other};
  }
  EXPECT_FALSE(robot.motors_enabled());  // a refused MOTOR_POWER did nothing
}

TEST_F(P2osRequests, SonarAnswersGeometryAndPower) {
  core::Device& sonar = devices.sonar();
  const auto reply = ask(sonar, Bytes{protocol::kSonarGetGeomReq});
  ASSERT_TRUE(acked(reply));
  EXPECT_EQ(reply->payload.size(), 387u);
  EXPECT_EQ(protocol::decode<protocol::SonarGeom>(reply->payload).pose_count, 16);
  EXPECT_TRUE(acked(ask(sonar, protocol::SonarPowerConfig{2, 0})));
  EXPECT_TRUE(nacked(ask(sonar, Bytes{protocol::kSonarGetGeomReq, 0})));
  EXPECT_TRUE(nacked(ask(sonar, Bytes{protocol::kSonarPowerReq})));
  EXPECT_TRUE(nacked(ask(sonar, Bytes{3, 0})));
}

TEST_F(P2osRequests, CmucamAnswersColourAndImagerParameters) {
  core::Device& camera = devices.device(protocol::kBlobfinderCode);
  EXPECT_TRUE(acked(ask(camera, protocol::BlobfinderColorConfig{1, -1, 0, 0, 0, 0, 0})));
  EXPECT_TRUE(acked(ask(camera, protocol::BlobfinderImagerConfig{2, 100, 50, 1, 0})));
  EXPECT_TRUE(acked(ask(camera, protocol::BlobfinderImagerConfig{2, -1, -1, -1, -1})));  // nothing to set
  EXPECT_TRUE(nacked(ask(camera, Bytes{protocol::kBlobfinderSetColorReq, 0, 0})));
  EXPECT_TRUE(nacked(ask(camera, Bytes{protocol::kBlobfinderSetImagerParamsReq})));
  EXPECT_TRUE(nacked(ask(camera, Bytes{3})));
}

TEST_F(P2osRequests, TheOtherDevicesNackEverything) {
  const std::vector<std::pair<core::Device*, Bytes>> cases = {
      {&devices.power(), Bytes{protocol::kMainPowerReq}},  // 1.5 NACKed it too
      {&devices.device(protocol::kBumperCode), Bytes{1}},  // bumper GET_GEOM, likewise
      {&devices.device(protocol::kGripperCode), Bytes{1}},
      {&devices.device(protocol::kAioCode), Bytes{1}},
      {&devices.device(protocol::kDioCode), Bytes{1}},
      {&devices.position(1), Bytes{protocol::kPositionGetGeomReq}},  // compass
      {&devices.position(2), Bytes{protocol::kPositionMotorPowerReq, 1}},  // gyro
      {&devices.device(protocol::kSoundCode), Bytes{1}},
  };
  for (const auto& [device, payload] : cases) EXPECT_TRUE(nacked(ask(*device, payload))) << device->name();
  EXPECT_FALSE(robot.motors_enabled());
}

}  // namespace p2os_requests_test
}  // namespace playerkit::drivers
