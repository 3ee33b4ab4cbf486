#include "sim/world/collisions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/world/world.hpp"
#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::collisions_test {

using world_test_support::fill_walls;
using world_test_support::mounted;
using world_test_support::object;
using world_test_support::open_floor;
using world_test_support::robot;
using world_test_support::run;
using world_test_support::walled_floor;

TEST(Collisions, AWallStopsTheRobotWhereItLastFitAndSetsStall) {
  World world({.step = 0.1}, walled_floor());
  const ModelId id = world.add(robot("r0", {}));
  world.set_active(id, true);
  world.command_velocity(id, {1.0, 0.0, 0.0});
  run(world, 18);  // the front (x + 0.2) is at 2.0, a cell short of the wall
  EXPECT_NEAR(world.true_pose(id).x, 1.8, 1e-9);
  EXPECT_FALSE(world.position(id).stalled);
  run(world, 5);
  EXPECT_NEAR(world.true_pose(id).x, 1.8, 1e-9);
  EXPECT_TRUE(world.position(id).stalled);
  EXPECT_EQ(world.position(id).velocity.x, 1.0);  // the command is kept
  // Backing away is a move that fits.
  world.command_velocity(id, {-0.5, 0.0, 0.0});
  world.step();
  EXPECT_NEAR(world.true_pose(id).x, 1.75, 1e-9);
  EXPECT_FALSE(world.position(id).stalled);
}

TEST(Collisions, TurningIntoAWallIsRefusedToo) {
  World world({.step = 0.1}, walled_floor());
  // A long thin robot alongside the wall: turning would swing its end in.
  ModelSpec spec = robot("r0", {2.0, 0.0, std::numbers::pi / 2});  // its side touches the wall
  spec.body.size = {1.0, 0.1};
  const ModelId id = world.add(spec);
  world.set_active(id, true);
  world.command_velocity(id, {0.0, 0.0, 1.0});
  run(world, 10);
  EXPECT_NEAR(world.true_pose(id).yaw, std::numbers::pi / 2, 1e-9);
  EXPECT_TRUE(world.position(id).stalled);
}

TEST(Collisions, RobotsDrivingIntoEachOtherBothStallWithoutOverlapping) {
  World world({.step = 0.1}, open_floor());
  const ModelId a = world.add(robot("a", {0.0, 0.0, 0.0}));
  const ModelId b = world.add(robot("b", {1.02, 0.1, std::numbers::pi}));
  for (const ModelId id : {a, b}) {
    world.set_active(id, true);
    world.command_velocity(id, {0.3, 0.0, 0.0});
  }
  run(world, 30);
  EXPECT_TRUE(world.position(a).stalled);
  EXPECT_TRUE(world.position(b).stalled);
  const double gap = world.true_pose(b).x - world.true_pose(a).x - 0.4;
  EXPECT_GE(gap, 0.0);
  EXPECT_LT(gap, 0.06);  // each moved while a 3 cm step still fitted
}

TEST(Collisions, ARobotNeverCollidesWithWhatRidesOnIt) {
  World world({.step = 0.1}, open_floor());
  const ModelId id = world.add(robot("r0", {}));
  ModelSpec laser = mounted(id, LaserSpec{}, {0.1, 0.0, 0.0});
  laser.body = {.shape = Shape::rectangle, .size = {0.155, 0.155}};  // inside the robot's own body
  world.add(laser);
  world.set_active(id, true);
  world.command_velocity(id, {0.5, 0.0, 0.5});
  run(world, 10);
  EXPECT_FALSE(world.position(id).stalled);
  EXPECT_NEAR(world.true_pose(id).yaw, 0.5, 1e-9);
}

TEST(Collisions, ModelsWithoutObstacleReturnArePassedThrough) {
  World world({.step = 0.1}, open_floor());
  ModelSpec ghost = object("ghost", {1.0, 0.0, 0.0}, Shape::rectangle, 0.3, 0.3);
  ghost.returns.obstacle = false;
  world.add(ghost);
  const ModelId id = world.add(robot("r0", {}));
  world.set_active(id, true);
  world.command_velocity(id, {1.0, 0.0, 0.0});
  run(world, 20);
  EXPECT_NEAR(world.true_pose(id).x, 2.0, 1e-9);
  EXPECT_FALSE(world.position(id).stalled);
  // A box that is an obstacle stops it.
  world.add(object("box", {3.0, 0.0, 0.0}, Shape::circle, 0.3, 0.3));
  run(world, 10);
  EXPECT_NEAR(world.true_pose(id).x, 2.6, 1e-9);  // front 2.8, the box from 2.85
  EXPECT_TRUE(world.position(id).stalled);
}

TEST(Collisions, AFastSmallRobotDoesNotJumpAThinWall) {
  grid::OccupancyGrid map = open_floor();
  fill_walls(map, 1.0, -10.0, 1.05, 10.0);  // one cell thick
  World world({.step = 0.1}, map);
  // 2 cm wide and 10 cm per step: checked at its end only, the move from
  // x = 0.97 to 1.07 would land beyond the wall.
  ModelSpec spec = robot("r0", {0.07, 0.0, 0.0});
  spec.body.size = {0.02, 0.02};
  const ModelId id = world.add(spec);
  world.set_active(id, true);
  world.command_velocity(id, {1.0, 0.0, 0.0});
  run(world, 20);
  EXPECT_NEAR(world.true_pose(id).x, 0.97, 1e-9);
  EXPECT_TRUE(world.position(id).stalled);
}

TEST(Collisions, BodyOverlapsWallsCountsAreaNotTouching) {
  // Binary fractions, so that touching is exact.
  grid::OccupancyGrid map(8, 8, 0.25, {-1.0, -1.0}, grid::CellState::free);
  map.set(4, 4, grid::CellState::occupied);  // [0, 0.25] x [0, 0.25]
  Body box{.shape = Shape::rectangle, .size = {0.5, 0.5}};
  EXPECT_TRUE(body_overlaps_walls(map, place_body(box, {0.0, 0.0, 0.0})));
  EXPECT_FALSE(body_overlaps_walls(map, place_body(box, {-0.25, 0.1, 0.0})));  // touches its edge
  EXPECT_TRUE(body_overlaps_walls(map, place_body(box, {-0.25, 0.1, std::numbers::pi / 4})));  // a corner dips in
  Body disc{.shape = Shape::circle, .size = {0.5, 0.5}};
  // The cell's corner (0, 0) is 0.354 from (-0.25, -0.25): outside the circle.
  EXPECT_FALSE(body_overlaps_walls(map, place_body(disc, {-0.25, -0.25, 0.0})));
  EXPECT_TRUE(body_overlaps_walls(map, place_body(disc, {-0.1, -0.1, 0.0})));
  EXPECT_FALSE(body_overlaps_walls(map, place_body(disc, {50.0, 50.0, 0.0})));  // off the map: open
}

}  // namespace playerkit::sim::collisions_test
