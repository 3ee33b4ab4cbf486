#include "families/nomad/driver/nomad_mapping.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace playerkit::drivers::nomad {
namespace nomad_mapping_test {

hardware::nomad::RobotState moving_state() {
  hardware::nomad::RobotState state;
  state.x = 1000;                    // 100 in
  state.y = -500;                    // -50 in
  state.steering = 3555;             // 355.5 deg
  state.translation_velocity = 100;  // 10 in/s
  state.steering_velocity = -150;
  state.turret_velocity = 300;
  state.sonar[0] = 255;
  state.sonar[15] = 10;
  state.ir[3] = 36;
  state.bumpers = 0b1000'0000'0000'0001;
  return state;
}

// nomad.md §2.1 with the reference's field mix-ups undone.
TEST(NomadMapping, EveryFieldInItsPlaceAndUnit) {
  const protocol::NomadData data = nomad_data(moving_state());
  EXPECT_EQ(data.x, 2540);
  EXPECT_EQ(data.y, -1270);  // 1.5: the steering angle x 2.54
  EXPECT_EQ(data.a, 356);    // 1.5: always 0
  EXPECT_EQ(data.vel_trans, 254);  // 1.5: the steering rate
  EXPECT_EQ(data.vel_steer, -15);  // 1.5: not byte-swapped
  EXPECT_EQ(data.vel_turret, 30);
  EXPECT_EQ(data.sonar[0], 6477);  // 255 in; 1.5 guessed 5000 mm
  EXPECT_EQ(data.sonar[15], 254);
  EXPECT_EQ(data.ir[3], 914);
  EXPECT_EQ(data.bumper[0], 1);
  EXPECT_EQ(data.bumper[1], 0);
  EXPECT_EQ(data.bumper[15], 1);
}

TEST(NomadMapping, CommandsInTheRobotsTenths) {
  EXPECT_EQ(velocity_words({.vel_trans = 254, .vel_steer = -15, .vel_turret = 30}), (VelocityWords{100, -150, 300}));
  EXPECT_EQ(velocity_words({.vel_trans = -1000, .vel_steer = 0, .vel_turret = 0}).translation, -394);
}

TEST(NomadMapping, ThePositionViewAndItsCommands) {
  const protocol::PositionData position = position_data(nomad_data(moving_state()));
  EXPECT_EQ(position.xpos, 2540);
  EXPECT_EQ(position.ypos, -1270);
  EXPECT_EQ(position.yaw, 356);
  EXPECT_EQ(position.xspeed, 254);
  EXPECT_EQ(position.yspeed, 0);
  EXPECT_EQ(position.yawspeed, -15);
  EXPECT_EQ(position.stall, 1);
  protocol::PositionCommand command;
  command.xspeed = 300;
  command.yspeed = 77;  // no sideways motion on a synchro drive; 1.5 drove the turret with it
  command.yawspeed = 20;
  const protocol::NomadCommand nomad = nomad_command(command);
  EXPECT_EQ(nomad.vel_trans, 300);
  EXPECT_EQ(nomad.vel_steer, 20);
  EXPECT_EQ(nomad.vel_turret, 20);
}

TEST(NomadMapping, TheSonarViewAndItsRing) {
  const protocol::SonarData sonar = sonar_data(nomad_data(moving_state()));
  EXPECT_EQ(sonar.range_count, 16);
  EXPECT_EQ(sonar.ranges[15], 254);
  EXPECT_EQ(sonar.ranges[16], 0);
  const auto poses = sonar_poses();
  ASSERT_EQ(poses.size(), 16U);
  EXPECT_NEAR(poses[0].x, 0.4, 1e-9);
  EXPECT_NEAR(poses[4].y, 0.4, 1e-9);
  EXPECT_NEAR(poses[1].yaw, 22.5 * M_PI / 180, 1e-9);
}

}  // namespace nomad_mapping_test
}  // namespace playerkit::drivers::nomad
