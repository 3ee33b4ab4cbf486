// gazebo.md §6's position checks on a world made here, through the
// simulated drivers as player-serve -s makes them.
#include <gtest/gtest.h>

#include "drivers/sim/sim_test_support.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::drivers::sim {
namespace sim_position_test {

using namespace testing;
using protocol::kPositionCode;
using protocol::PositionCommand;
using protocol::PositionData;

World robot_world() {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot"));
  world.add(on(robot, "robot.truth", TruthSpec{}));
  return world;
}

std::vector<std::uint8_t> velocity(int xspeed, int yspeed, int yawspeed) {
  PositionCommand command;
  command.xspeed = xspeed;
  command.yspeed = yspeed;
  command.yawspeed = yawspeed;
  command.state = 1;
  return protocol::encode(command);
}

struct PositionFixture : ::testing::Test {
  void SetUp() override {
    sim.load("position:0 ( driver \"position\" model \"robot\" )\n");
    ASSERT_TRUE(position().subscribe());
  }
  core::Device& position() { return sim.device(kPositionCode); }
  void command(const std::vector<std::uint8_t>& payload) {
    ASSERT_EQ(position().put_command(1, payload), core::Device::CommandStatus::kAccepted);
    sim.cycle(position());
  }
  SimDevices sim{robot_world()};
};

TEST_F(PositionFixture, HalfAMetrePerSecondForTwoSecondsIsOneMetre) {
  command(velocity(500, 0, 0));
  sim.step(20);  // 2 s of simulation
  sim.cycle(position());
  const auto data = sim.latest<PositionData>(position());
  EXPECT_NEAR(data.xpos, 500 * 2.0, 1);  // v·t in mm
  EXPECT_NEAR(data.ypos, 0, 1);
  EXPECT_EQ(data.yaw, 0);
  EXPECT_EQ(data.xspeed, 500);
  EXPECT_EQ(data.stall, 0);
  // Stamped with the simulation time of the reading, which is the server's clock.
  EXPECT_EQ(position().latest_data()->timestamp, (protocol::Timestamp{2, 0}));
  EXPECT_EQ(sim.builtin.clock.now(), (protocol::Timestamp{2, 0}));
}

TEST_F(PositionFixture, NinetyDegreesPerSecondForOneSecondIsNinetyDegrees) {
  command(velocity(0, 0, 90));
  sim.step(10);
  sim.cycle(position());
  const auto data = sim.latest<PositionData>(position());
  EXPECT_NEAR(data.yaw, 90, 1);
  EXPECT_EQ(data.yawspeed, 90);
  EXPECT_NEAR(data.xpos, 0, 1);
}

TEST_F(PositionFixture, HeadingIsReportedFrom0To359AsStage13Did) {
  command(velocity(0, 0, -90));
  sim.step(10);  // -90°
  sim.cycle(position());
  EXPECT_NEAR(sim.latest<PositionData>(position()).yaw, 270, 1);
}

TEST_F(PositionFixture, APositionGoalIsDrivenTo) {
  PositionCommand goal;
  goal.xpos = 1000;
  goal.ypos = 0;
  goal.type = 1;
  command(protocol::encode(goal));
  sim.step(60);  // 1 m at Stage's go-to cap of 0.4 m/s takes 2.5 s
  sim.cycle(position());
  EXPECT_NEAR(sim.latest<PositionData>(position()).xpos, 1000, 20);  // its 2 cm tolerance
}

TEST_F(PositionFixture, PublishesEveryStepAndNothingWhilePaused) {
  // Every step's reading, as the step happens: a recorder or amcl listening
  // gets each one, however fast the world runs and however rarely the server
  // cycles (found: --speedup 0 recorded only the last step).
  struct Timestamps final : core::DeviceListener {
    void data_published(const core::Device& device) override { seen.push_back(device.latest_data()->timestamp); }
    void replies_ready(const core::Device&) override {}
    std::vector<protocol::Timestamp> seen;
  } listener;
  position().add_listener(&listener);
  sim.cycle(position());
  EXPECT_EQ(position().latest_data()->sequence, 0u);  // nothing taken since the subscription
  sim.step();
  EXPECT_EQ(position().latest_data()->sequence, 1u);
  EXPECT_EQ(position().latest_data()->timestamp, (protocol::Timestamp{0, 100000}));
  sim.cycle(position());
  sim.cycle(position());
  EXPECT_EQ(position().latest_data()->sequence, 1u);  // paused: nothing new
  sim.step(3);
  EXPECT_EQ(position().latest_data()->sequence, 4u);
  position().remove_listener(&listener);
  EXPECT_EQ(listener.seen, (std::vector<protocol::Timestamp>{{0, 100000}, {0, 200000}, {0, 300000}, {0, 400000}}));
}

TEST_F(PositionFixture, GeometryIsTheBodysOffsetAndSize) {
  const core::Reply reply = sim.ask(position(), {protocol::kPositionGetGeomReq});
  ASSERT_EQ(reply.type, protocol::MessageType::kAck);
  const auto geom = protocol::decode<protocol::PositionGeom>(reply.payload);
  EXPECT_EQ(geom.subtype, protocol::kPositionGetGeomReq);
  EXPECT_EQ(geom.pose, (std::array<std::int16_t, 3>{0, 0, 0}));
  EXPECT_EQ(geom.size, (std::array<std::uint16_t, 2>{530, 380}));
}

TEST_F(PositionFixture, ModeAndPowerRequestsAreAcknowledged) {
  EXPECT_EQ(sim.ask(position(), {protocol::kPositionMotorPowerReq, 1}).type, protocol::MessageType::kAck);
  EXPECT_EQ(sim.ask(position(), {protocol::kPositionVelocityModeReq, 0}).type, protocol::MessageType::kAck);
  EXPECT_EQ(sim.ask(position(), {protocol::kPositionPositionModeReq, 1}).type, protocol::MessageType::kAck);
  EXPECT_EQ(sim.ask(position(), {protocol::kPositionSpeedPidReq}).type, protocol::MessageType::kNack);
}

TEST_F(PositionFixture, SetOdometryAndResetOdometryMoveTheReportedPose) {
  protocol::PositionSetOdomRequest set;
  set.subtype = protocol::kPositionSetOdomReq;
  set.x = 1500;
  set.y = -250;
  set.theta = 45;
  EXPECT_EQ(sim.ask(position(), protocol::encode(set)).type, protocol::MessageType::kAck);
  sim.step();
  sim.cycle(position());
  auto data = sim.latest<PositionData>(position());
  EXPECT_EQ(data.xpos, 1500);
  EXPECT_EQ(data.ypos, -250);
  EXPECT_EQ(data.yaw, 45);
  EXPECT_EQ(sim.ask(position(), {protocol::kPositionResetOdomReq}).type, protocol::MessageType::kAck);
  sim.step();
  sim.cycle(position());
  data = sim.latest<PositionData>(position());
  EXPECT_EQ(data.xpos, 0);
  EXPECT_EQ(data.ypos, 0);
  EXPECT_EQ(data.yaw, 0);
}

TEST_F(PositionFixture, TheLastUnsubscriptionStopsTheRobot) {
  command(velocity(500, 0, 0));
  sim.step(10);
  position().unsubscribe();
  sim.step(10);  // nobody subscribed: it stands still
  ASSERT_TRUE(position().subscribe());
  sim.step();
  sim.cycle(position());
  const auto data = sim.latest<PositionData>(position());
  EXPECT_NEAR(data.xpos, 500, 1);
  EXPECT_EQ(data.xspeed, 0);
}

TEST(SimPositionTwoDevicesTest, OneModelServedTwiceKeepsMovingWhileEitherIsSubscribed) {
  SimDevices sim{robot_world()};
  sim.load("position:0 ( driver \"position\" model \"robot\" )\n"
           "position:1 ( driver \"gz_position\" gz_id \"robot\" )\n");
  core::Device& stage = sim.device(kPositionCode, 0);
  core::Device& gazebo = sim.device(kPositionCode, 1);
  ASSERT_TRUE(stage.subscribe());
  ASSERT_TRUE(gazebo.subscribe());
  ASSERT_EQ(gazebo.put_command(1, velocity(1000, 0, -90)), core::Device::CommandStatus::kAccepted);
  sim.cycle(gazebo);
  stage.unsubscribe();  // the other still holds the robot
  sim.step(5);
  sim.cycle(gazebo);
  const auto data = sim.latest<PositionData>(gazebo);
  EXPECT_GT(data.xpos, 300);
  EXPECT_EQ(data.yaw, -45);  // gz_position reports -180..180, as Gazebo did
  gazebo.unsubscribe();
}

}  // namespace sim_position_test
}  // namespace playerkit::drivers::sim
