// Odometry and gps of position models (motion.cpp).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/world/world.hpp"
#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::motion_test {

using world_test_support::fill_walls;
using world_test_support::open_floor;
using world_test_support::robot;
using world_test_support::run;

constexpr double kStep = 0.1;

void expect_pose_near(const geometry::Pose2& actual, const geometry::Pose2& expected, double tolerance = 1e-9) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(geometry::angle_difference(actual.yaw, expected.yaw), 0.0, tolerance);
}

struct Driven {
  World world;
  ModelId id;
};

Driven driven(PositionSpec spec, const geometry::Pose2& start = {}, std::uint64_t seed = 3,
              grid::OccupancyGrid map = open_floor()) {
  Driven setup{World({.step = kStep, .seed = seed}, std::move(map)), kNoModel};
  setup.id = setup.world.add(robot("r0", start, std::move(spec)));
  setup.world.set_active(setup.id, true);
  return setup;
}

TEST(Odometry, WithoutErrorItIsTheTrueMotionInTheStartFrame) {
  const geometry::Pose2 start{2.0, 1.0, 0.5};
  auto [world, id] = driven({}, start);
  EXPECT_EQ(world.position(id).pose, geometry::Pose2{});
  world.command_velocity(id, {0.4, 0.0, 0.3});
  run(world, 30);
  expect_pose_near(world.position(id).pose, start.between(world.true_pose(id)));
  EXPECT_NEAR(world.position(id).time, 3.0, 1e-12);
}

TEST(Odometry, ErrorsScaleEachPartOfEveryStep) {
  PositionSpec spec;
  spec.drive = Drive::omnidirectional;
  spec.odom_error = Eigen::Vector3d(0.1, -0.2, 0.05);
  auto [world, id] = driven(spec);
  const Eigen::Vector3d velocity{0.3, 0.1, 0.4};
  world.command_velocity(id, velocity);
  // The test's own integration: each step's motion, scaled, composed on.
  geometry::Pose2 odometry;
  for (int i = 0; i < 25; ++i) {
    const geometry::Pose2 scaled{velocity.x() * kStep * 1.1, velocity.y() * kStep * 0.8, velocity.z() * kStep * 1.05};
    odometry = odometry.compose(scaled);
    world.step();
  }
  expect_pose_near(world.position(id).pose, odometry);
}

TEST(Odometry, AnOverReadingWheelReportsFurtherAndTurnsFurther) {
  PositionSpec spec;
  spec.odom_error = Eigen::Vector3d(0.02, 0.0, -0.04);
  auto [world, id] = driven(spec);
  world.command_velocity(id, {0.5, 0.0, 0.0});
  run(world, 20);  // 1 m
  EXPECT_NEAR(world.position(id).pose.x, 1.02, 1e-9);
  EXPECT_NEAR(world.true_pose(id).x, 1.0, 1e-9);
  world.command_velocity(id, {0.0, 0.0, 0.5});
  run(world, 20);  // 1 rad
  EXPECT_NEAR(world.position(id).pose.yaw, 0.96, 1e-9);
}

TEST(Odometry, TheDefaultErrorIsDrawnFromTheSeedWithinStagesBounds) {
  PositionSpec spec;
  spec.odom_error.reset();
  const auto drive_and_read = [&](std::uint64_t seed) {
    auto [world, id] = driven(spec, {}, seed);
    world.command_velocity(id, {0.5, 0.0, 0.0});
    run(world, 20);
    const double x = world.position(id).pose.x;
    world.command_velocity(id, {0.0, 0.0, 0.5});
    run(world, 20);
    return Eigen::Vector2d(x, world.position(id).pose.yaw);
  };
  const Eigen::Vector2d first = drive_and_read(11);
  EXPECT_EQ(drive_and_read(11), first);
  EXPECT_NE(drive_and_read(12), first);
  EXPECT_NE(first.x(), 1.0);
  EXPECT_LE(std::abs(first.x() - 1.0), 0.015 + 1e-12);
  EXPECT_LE(std::abs(first.y() - 1.0), 0.025 + 1e-12);
}

TEST(Odometry, StalledMovesDoNotAdvanceIt) {
  grid::OccupancyGrid map = open_floor();
  fill_walls(map, 2.05, -10.0, 2.5, 10.0);
  auto [world, id] = driven({}, {}, 3, map);
  world.command_velocity(id, {1.0, 0.0, 0.0});
  run(world, 30);
  EXPECT_TRUE(world.position(id).stalled);
  EXPECT_NEAR(world.position(id).pose.x, 1.8, 1e-9);  // Stage 1.3, not Stage 4
}

TEST(Odometry, SetOdometryMovesTheReportAndMotionContinuesFromIt) {
  auto [world, id] = driven({}, {1.0, 1.0, 0.0});
  world.set_odometry(id, {5.0, 0.0, std::numbers::pi / 2});
  EXPECT_EQ(world.position(id).pose, (geometry::Pose2{5.0, 0.0, std::numbers::pi / 2}));
  world.command_velocity(id, {0.5, 0.0, 0.0});
  run(world, 10);
  expect_pose_near(world.position(id).pose, {5.0, 0.5, std::numbers::pi / 2});
}

TEST(Odometry, ATeleportIsNotSeenByOdometry) {
  auto [world, id] = driven({});
  world.command_velocity(id, {0.5, 0.0, 0.0});
  run(world, 10);
  world.set_true_pose(id, {-3.0, 4.0, 1.0});
  expect_pose_near(world.true_pose(id), {-3.0, 4.0, 1.0});
  world.step();
  expect_pose_near(world.position(id).pose, {0.55, 0.0, 0.0});
}

TEST(Gps, ReportsTheTruePoseInTheLocalizationFrame) {
  PositionSpec spec;
  spec.localization = Localization::gps;
  spec.odom_error = Eigen::Vector3d(0.3, 0.3, 0.3);  // ignored by gps
  const geometry::Pose2 start{1.0, -2.0, 0.7};
  auto [world, id] = driven(spec, start);
  world.command_velocity(id, {0.4, 0.0, -0.2});
  run(world, 15);
  world.set_true_pose(id, {0.5, 0.5, 0.0});  // gps does see jumps
  run(world, 15);
  expect_pose_near(world.position(id).pose, start.between(world.true_pose(id)));

  spec.localization_origin = geometry::Pose2{};  // the world frame (Stage's stock worlds)
  auto [global_world, global_id] = driven(spec, start);
  global_world.command_velocity(global_id, {0.4, 0.0, -0.2});
  run(global_world, 15);
  expect_pose_near(global_world.position(global_id).pose, global_world.true_pose(global_id));
  // set_odometry moves the frame so that the true pose reads as given.
  global_world.set_odometry(global_id, {0.0, 0.0, 0.0});
  global_world.command_velocity(global_id, {0.5, 0.0, 0.0});
  run(global_world, 4);
  expect_pose_near(global_world.position(global_id).pose, {0.2, 0.0, 0.0});
}

}  // namespace playerkit::sim::motion_test
