#include "sim/world/kinematics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/world/world.hpp"
#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::kinematics_test {

using world_test_support::open_floor;
using world_test_support::robot;
using world_test_support::run;

constexpr double kStep = 0.1;

struct OneRobot {
  World world;
  ModelId id;
};

OneRobot one_robot(PositionSpec position = {}, const geometry::Pose2& start = {}) {
  OneRobot setup{World({.step = kStep, .seed = 1}, open_floor()), kNoModel};
  setup.id = setup.world.add(robot("r0", start, std::move(position)));
  setup.world.set_active(setup.id, true);
  return setup;
}

void expect_pose_near(const geometry::Pose2& actual, const geometry::Pose2& expected, double tolerance = 1e-9) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(geometry::angle_difference(actual.yaw, expected.yaw), 0.0, tolerance);
}

TEST(Kinematics, AStraightLineCoversSpeedTimesTimeAlongTheHeading) {
  auto [world, id] = one_robot({}, {1.0, 2.0, std::numbers::pi / 6});
  world.command_velocity(id, {0.5, 0.0, 0.0});
  run(world, 20);
  EXPECT_NEAR(world.time(), 2.0, 1e-12);
  expect_pose_near(world.true_pose(id), {1.0 + std::cos(std::numbers::pi / 6), 2.0 + std::sin(std::numbers::pi / 6),
                                         std::numbers::pi / 6});
}

TEST(Kinematics, AnInPlaceTurnTurnsByRateTimesTime) {
  auto [world, id] = one_robot({}, {1.0, -1.0, 0.0});
  world.command_velocity(id, {0.0, 0.0, -0.5});
  run(world, 10);
  expect_pose_near(world.true_pose(id), {1.0, -1.0, -0.5});
}

TEST(Kinematics, AnArcIsStageStepsTranslateAlongTheHeadingThenTurn) {
  auto [world, id] = one_robot();
  const double v = 0.4, w = 0.3;
  world.command_velocity(id, {v, 0.0, w});
  // Stage's integration, step by step (stage-worlds.md §2.5).
  double x = 0.0, y = 0.0, a = 0.0;
  for (int i = 0; i < 50; ++i) {
    x += v * kStep * std::cos(a);
    y += v * kStep * std::sin(a);
    a += w * kStep;
    world.step();
  }
  expect_pose_near(world.true_pose(id), {x, y, a});
  // The path is a circle of radius v/w through the origin, seen turned by
  // half a step's turn (each step moves along the heading at its start).
  const geometry::Pose2 on_circle =
      geometry::Pose2{0.0, 0.0, -w * kStep / 2.0}.compose({v / w * std::sin(a), v / w * (1.0 - std::cos(a)), 0.0});
  const double chord_scale = (w * kStep / 2.0) / std::sin(w * kStep / 2.0);
  EXPECT_NEAR(x, chord_scale * on_circle.x, 1e-9);
  EXPECT_NEAR(y, chord_scale * on_circle.y, 1e-9);
}

TEST(Kinematics, CommandsAreClampedToTheVelocityBounds) {
  PositionSpec spec;
  spec.min_velocity = {-0.2, -1.0, -0.3};
  spec.max_velocity = {0.7, 1.0, 0.3};
  auto [world, id] = one_robot(spec);
  world.command_velocity(id, {5.0, 0.0, 2.0});
  world.step();
  EXPECT_EQ(world.position(id).velocity, (geometry::Pose2{0.7, 0.0, 0.3}));
  world.command_velocity(id, {-5.0, 0.0, -2.0});
  world.step();
  EXPECT_EQ(world.position(id).velocity, (geometry::Pose2{-0.2, 0.0, -0.3}));
}

TEST(Kinematics, AccelerationLimitsRampTheVelocityAndThePoseFollowsTheRamp) {
  PositionSpec spec;
  spec.max_acceleration = {0.5, 0.5, 1.0};
  auto [world, id] = one_robot(spec);
  world.command_velocity(id, {0.3, 0.0, 0.0});
  double expected_x = 0.0;
  for (int i = 1; i <= 10; ++i) {
    world.step();
    const double v = std::min(0.05 * i, 0.3);  // 0.5 m/s² · 0.1 s per step
    expected_x += v * kStep;
    EXPECT_NEAR(world.position(id).velocity.x, v, 1e-12) << "step " << i;
  }
  EXPECT_NEAR(world.true_pose(id).x, expected_x, 1e-12);
  // Slowing down is limited too.
  world.command_velocity(id, {0.0, 0.0, 0.0});
  world.step();
  EXPECT_NEAR(world.position(id).velocity.x, 0.25, 1e-12);
}

TEST(Kinematics, AnOmnidirectionalBaseMovesSideways) {
  PositionSpec spec;
  spec.drive = Drive::omnidirectional;
  auto [world, id] = one_robot(spec, {0.0, 0.0, std::numbers::pi / 2});
  world.command_velocity(id, {0.0, 0.3, 0.0});
  run(world, 10);
  // Left of a robot facing +y is -x.
  expect_pose_near(world.true_pose(id), {-0.3, 0.0, std::numbers::pi / 2});
}

TEST(Kinematics, ADifferentialBaseIgnoresSidewaysCommands) {
  auto [world, id] = one_robot();
  world.command_velocity(id, {0.2, 0.5, 0.0});
  run(world, 10);
  expect_pose_near(world.true_pose(id), {0.2, 0.0, 0.0});
  EXPECT_EQ(world.position(id).velocity.y, 0.0);
}

TEST(Kinematics, ACarTurnsBySpeedTimesSineOfSteeringOverWheelbase) {
  PositionSpec spec;
  spec.drive = Drive::car;
  spec.wheelbase = 0.5;
  auto [world, id] = one_robot(spec);
  const double v = 0.5, steering = 0.3;
  world.command_velocity(id, {v, 0.0, steering});
  world.step();
  const geometry::Pose2 velocity = world.position(id).velocity;
  EXPECT_NEAR(velocity.x, v * std::cos(steering), 1e-12);
  EXPECT_NEAR(velocity.yaw, v * std::sin(steering) / 0.5, 1e-12);
  EXPECT_EQ(velocity.y, 0.0);
}

TEST(Kinematics, OnlyActiveModelsMoveAndTheLastDeactivationStopsThem) {
  auto [world, id] = one_robot();
  world.command_velocity(id, {0.5, 0.0, 0.0});
  world.step();
  world.set_active(id, false);
  run(world, 5);
  expect_pose_near(world.true_pose(id), {0.05, 0.0, 0.0});
  world.set_active(id, true);
  run(world, 5);  // the command was dropped with the last subscription
  expect_pose_near(world.true_pose(id), {0.05, 0.0, 0.0});
  EXPECT_EQ(world.position(id).velocity, geometry::Pose2{});
}

TEST(Kinematics, AnInitialVelocityMovesTheModelUnsubscribed) {
  PositionSpec spec;
  spec.initial_velocity = {0.1, 0.0, 0.0};
  World world({.step = kStep}, open_floor());
  const ModelId id = world.add(robot("r0", {}, spec));
  run(world, 10);
  expect_pose_near(world.true_pose(id), {0.1, 0.0, 0.0});
}

TEST(Kinematics, ChildrenRideOnTheirParent) {
  auto [world, id] = one_robot();
  const ModelId laser = world.add(world_test_support::mounted(id, LaserSpec{}, {0.1, 0.05, 0.2}));
  world.command_velocity(id, {0.3, 0.0, 0.4});
  run(world, 7);
  expect_pose_near(world.true_pose(laser), world.true_pose(id).compose({0.1, 0.05, 0.2}));
  expect_pose_near(world.scene().model(laser).pose, world.true_pose(laser));
}

TEST(Kinematics, GoToReachesTheGoalPoseWithinTolerance) {
  for (const Drive drive : {Drive::differential, Drive::omnidirectional}) {
    PositionSpec spec;
    spec.drive = drive;
    auto [world, id] = one_robot(spec);
    const geometry::Pose2 goal{1.0, -0.6, 2.0};
    world.command_pose(id, goal);
    run(world, 200);
    const geometry::Pose2 pose = world.position(id).pose;
    EXPECT_LT(std::hypot(pose.x - goal.x, pose.y - goal.y), 0.02) << "drive " << static_cast<int>(drive);
    EXPECT_LT(std::abs(geometry::angle_difference(pose.yaw, goal.yaw)), std::numbers::pi / 180.0);
    EXPECT_EQ(world.position(id).velocity, geometry::Pose2{});
  }
}

TEST(Kinematics, GoToRespectsStagesSpeedCaps) {
  auto [world, id] = one_robot();
  world.command_pose(id, {0.0, 0.0, 3.0});
  run(world, 3);
  EXPECT_NEAR(world.position(id).velocity.yaw, 1.0, 1e-12);
  world.command_pose(id, {5.0, 0.0, 0.0});
  world.step();
  EXPECT_NEAR(world.position(id).velocity.x, 0.0, 1e-12);  // turning back to face it first
  EXPECT_NEAR(world.position(id).velocity.yaw, -1.0, 1e-12);
  run(world, 40);
  EXPECT_NEAR(world.position(id).velocity.x, 0.4, 1e-12);
  // A velocity command ends the go-to.
  world.command_velocity(id, {-0.1, 0.0, 0.0});
  world.step();
  EXPECT_NEAR(world.position(id).velocity.x, -0.1, 1e-12);
}

TEST(Kinematics, PureFunctionsAgreeWithTheWorld) {
  PositionSpec spec;
  spec.max_acceleration = {1.0, 1.0, 1.0};
  const Eigen::Vector3d velocity = accelerate(Eigen::Vector3d::Zero(), drive_velocity(spec, {2.0, 3.0, -4.0}),
                                              spec.max_acceleration, 0.1);
  EXPECT_TRUE(velocity.isApprox(Eigen::Vector3d(0.1, 0.0, -0.1)));
  const geometry::Pose2 motion = step_motion({1.0, 2.0, 3.0}, 0.5);
  EXPECT_EQ(motion, (geometry::Pose2{0.5, 1.0, 1.5}));
  EXPECT_EQ(odometry_motion(motion, {0.1, -0.1, 0.0}), (geometry::Pose2{0.5 * 1.1, 1.0 * 0.9, 1.5}));
}

}  // namespace playerkit::sim::kinematics_test
