#include "families/nomad/emulator/nomad_emulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "algorithms/grid/occupancy_grid.hpp"

namespace playerkit::emulators {
namespace nomad_emulator_test {

using namespace std::chrono_literals;
namespace nomad = hardware::nomad;
namespace type = hardware::nomad::message_type;

// A client in lock-step with the server on a simulated clock.
struct Client {
  explicit Client(NomadEmulatorOptions options = {}) : robot(options) {}
  NomadEmulator robot;
  Duration now{0};

  // Sends one request and waits for its one reply.
  nomad::Message ask(const nomad::Message& request) {
    const auto bytes = nomad::encode(request);
    robot.receive(bytes, now, 0);
    for (;;) {
      auto out = robot.take_output();
      if (!out.empty()) {
        EXPECT_EQ(out.size(), 1U);
        EXPECT_FALSE(out.front().has_checksum);
        return nomad::decode(out.front().bytes).value();
      }
      EXPECT_NE(robot.next_deadline(), Duration::max());
      now = robot.next_deadline();
      robot.advance(now);
    }
  }
  nomad::RobotState state() { return nomad::parse_state(ask(nomad::get_state())).value(); }
  void wait(Duration duration) {
    now += duration;
    robot.advance(now);
  }
  // The reference driver's setup (nomad.md §1.3).
  void set_up_like_player() {
    ask(nomad::connect_robot(1234));
    ask(nomad::sensor_mask());
    ask(nomad::command_timeout(5));
    ask(nomad::zero());
    ask(nomad::accelerations(nomad::kSetupAccelerations));
    ask(nomad::speeds(nomad::kSetupSpeeds));
  }
};

TEST(NomadEmulator, ConnectAnswersANonZeroPortAndEverythingElseAState) {
  Client client;
  const nomad::Message connect = client.ask(nomad::connect_robot(99));
  EXPECT_EQ(connect.type, type::kConnectRobot);
  ASSERT_EQ(connect.words.size(), 1U);
  EXPECT_NE(connect.words[0], 0);
  EXPECT_TRUE(client.robot.connected());
  for (const auto& request : {nomad::sensor_mask(), nomad::command_timeout(5), nomad::zero(),
                              nomad::accelerations(nomad::kSetupAccelerations), nomad::speeds(nomad::kSetupSpeeds),
                              nomad::velocity(0, 0, 0), nomad::get_state()}) {
    const nomad::Message reply = client.ask(request);
    EXPECT_EQ(reply.type, type::kState) << nomad::type_name(request.type);
    EXPECT_EQ(reply.words.size(), nomad::kStateWords);
    EXPECT_EQ(reply.words[45], 0) << "no laser points";
  }
}

TEST(NomadEmulator, RepliesComeAfterTheDelayAndRequestsSplitAnywhereStillCount) {
  Client client;
  const auto bytes = nomad::encode(nomad::velocity(1, 2, 3));
  client.robot.receive(std::span(bytes).first(5), 0ms, 0);
  client.robot.receive(std::span(bytes).subspan(5), 1ms, 0);
  EXPECT_TRUE(client.robot.take_output().empty());
  EXPECT_EQ(client.robot.next_deadline(), 21ms);
  client.robot.advance(21ms);
  EXPECT_EQ(client.robot.take_output().size(), 1U);
  EXPECT_EQ(client.robot.requests_of(type::kVelocityMode), 1U);
}

TEST(NomadEmulator, DrivesAlongTheSteeringAngle) {
  Client client;
  client.set_up_like_player();
  client.ask(nomad::velocity(100, 0, 0));  // 10 in/s
  client.wait(2s);
  auto state = client.state();
  EXPECT_NEAR(state.x, 200 + 4, 2);  // 20 in, plus the replies' time
  EXPECT_EQ(state.y, 0);
  EXPECT_EQ(state.translation_velocity, 100);
  // A quarter turn at 45 deg/s, then straight on along +y.
  client.ask(nomad::velocity(0, 450, 450));
  client.wait(2s - 40ms);
  state = client.state();
  EXPECT_NEAR(state.steering, 900, 2);
  EXPECT_NEAR(state.turret, 900, 2);
  const std::int32_t x_before = state.x;
  client.ask(nomad::velocity(100, 0, 0));
  client.wait(1s);
  state = client.state();
  EXPECT_NEAR(state.x, x_before, 2);
  EXPECT_NEAR(state.y, 100, 6);
  EXPECT_NEAR(client.robot.true_pose().yaw, std::numbers::pi / 2, 0.01);
}

TEST(NomadEmulator, ZeroResetsPositionAndAngles) {
  Client client;
  client.set_up_like_player();
  client.ask(nomad::velocity(100, 100, 0));
  client.wait(1s);
  client.ask(nomad::zero());
  const auto state = client.state();
  EXPECT_EQ(state.x, 0);
  EXPECT_EQ(state.y, 0);
  EXPECT_EQ(state.steering, 0);
  EXPECT_EQ(state.translation_velocity, 0);
}

TEST(NomadEmulator, StopsWhenNoVelocityCommandCameWithinTheTimeout) {
  Client client;
  client.set_up_like_player();  // CONF_TM 5
  client.ask(nomad::velocity(100, 0, 0));
  client.wait(4900ms);
  EXPECT_EQ(client.robot.state().translation_velocity, 100);
  client.wait(200ms);
  EXPECT_EQ(client.robot.state().translation_velocity, 0);
  EXPECT_NEAR(client.robot.state().x, 500, 3);  // 5 s at 10 in/s, then still
}

TEST(NomadEmulator, OdometryCarriesTheConfiguredError) {
  NomadEmulatorOptions options;
  options.odometry_error.translation_scale = 0.1;
  options.start_pose = {1.0, 2.0, 0.0};
  Client client(options);
  client.ask(nomad::velocity(100, 0, 0));
  client.wait(10s - 20ms);
  EXPECT_NEAR(client.state().x, 1100, 4);
  EXPECT_NEAR(client.robot.true_pose().x, 1.0 + 1000 * 0.00254, 0.01);
  EXPECT_NEAR(client.robot.world_pose()->y, 2.0, 1e-9);
}

TEST(NomadEmulator, HeadingDriftAndNoiseFollowTheDistanceDrivenAndTheSeed) {
  NomadEmulatorOptions options;
  options.odometry_error.heading_drift_per_metre = 0.1;  // rad
  options.odometry_error.translation_noise = 0.01;
  options.odometry_error.seed = 7;
  Client first(options);
  Client second(options);
  for (Client* client : {&first, &second}) {
    client->ask(nomad::velocity(394, 0, 0));  // 1 m/s
    client->wait(1s - 20ms);
  }
  const auto state = first.state();
  const auto same = second.state();
  EXPECT_NEAR(state.steering, 57, 2);  // 0.1 rad in tenths of a degree
  EXPECT_EQ(state.steering, same.steering);
  EXPECT_EQ(state.x, same.x);
  EXPECT_NEAR(first.robot.true_pose().yaw, 0.0, 1e-9);
}

TEST(NomadEmulator, SensorsSeeTheMapAndAWallStopsTheBody) {
  // A wall 1 m ahead (x = 1.0 .. 1.1), free space elsewhere.
  grid::OccupancyGrid map(60, 60, 0.05, {-1.5, -1.5}, grid::CellState::free);
  for (int row = 0; row < 60; ++row) {
    map.set(50, row, grid::CellState::occupied);
    map.set(51, row, grid::CellState::occupied);
  }
  NomadEmulatorOptions options;
  options.map = &map;
  Client client(options);
  auto state = client.state();
  EXPECT_NEAR(state.sonar[0], (1.0 - 0.4) / 0.0254, 1);  // straight ahead
  EXPECT_EQ(state.sonar[8], 255);                        // nothing behind within range
  EXPECT_NEAR(state.ir[0], 24, 1);
  EXPECT_EQ(state.ir[8], 36);
  client.ask(nomad::velocity(200, 0, 0));
  client.wait(10s);
  state = client.state();
  EXPECT_NEAR(client.robot.true_pose().x, 1.0 - 0.4, 0.02);
  EXPECT_TRUE(state.bumpers & 1);
  client.ask(nomad::velocity(-200, 0, 0));  // backing away is allowed
  client.wait(1s);
  EXPECT_LT(client.robot.true_pose().x, 0.3);
  EXPECT_EQ(client.state().bumpers, 0);
}

TEST(NomadEmulator, AClientThatLeavesIsOwedNothing) {
  Client client;
  client.robot.receive(nomad::encode(nomad::get_state()), 0ms, 0);
  client.robot.host_disconnected(5ms);
  client.robot.advance(100ms);
  EXPECT_TRUE(client.robot.take_output().empty());
  EXPECT_FALSE(client.robot.connected());
}

}  // namespace nomad_emulator_test
}  // namespace playerkit::emulators
