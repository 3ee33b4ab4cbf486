#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/world/world.hpp"
#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::gripper_test {

using world_test_support::mounted;
using world_test_support::object;
using world_test_support::open_floor;
using world_test_support::robot;
using world_test_support::run;

// A robot at the origin facing +x with a gripper 0.1 deep and 0.3 wide in
// front, its front edge at x = 0.3; the paddles reach 0.1 beyond, to 0.4.
struct GripperRig {
  World world{{.step = 0.1}, open_floor()};
  ModelId robot_id = kNoModel;
  ModelId gripper_id = kNoModel;
};

GripperRig gripper_rig(GripperSpec spec = {}) {
  GripperRig rig;
  rig.robot_id = rig.world.add(robot("r0", {}));
  ModelSpec gripper = mounted(rig.robot_id, spec, {0.25, 0.0, 0.0});
  gripper.body = {.shape = Shape::rectangle, .size = {0.1, 0.3}};
  rig.gripper_id = rig.world.add(gripper);
  rig.world.set_active(rig.robot_id, true);
  rig.world.set_active(rig.gripper_id, true);
  return rig;
}

ModelId add_puck(World& world, const std::string& name, double x, double y, bool grippable = true) {
  ModelSpec puck = object(name, {x, y, 0.0}, Shape::circle, 0.08, 0.08);
  puck.returns.obstacle = false;
  puck.returns.gripper = grippable;
  return world.add(puck);
}

void expect_pose_near(const geometry::Pose2& actual, const geometry::Pose2& expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-9);
  EXPECT_NEAR(actual.y, expected.y, 1e-9);
  EXPECT_NEAR(geometry::angle_difference(actual.yaw, expected.yaw), 0.0, 1e-9);
}

TEST(Gripper, BeamsSeeGrippableModelsBetweenAndJustAheadOfThePaddles) {
  GripperRig rig = gripper_rig();
  World& world = rig.world;
  world.step();
  EXPECT_FALSE(world.gripper(rig.gripper_id).inner_beam);
  EXPECT_FALSE(world.gripper(rig.gripper_id).outer_beam);
  const ModelId far = add_puck(world, "far", 0.45, 0.0);
  world.step();
  EXPECT_FALSE(world.gripper(rig.gripper_id).inner_beam);
  EXPECT_TRUE(world.gripper(rig.gripper_id).outer_beam);
  world.set_true_pose(far, {0.35, 0.1, 0.0});
  world.step();
  EXPECT_TRUE(world.gripper(rig.gripper_id).inner_beam);
  EXPECT_FALSE(world.gripper(rig.gripper_id).outer_beam);
  world.set_true_pose(far, {0.35, 0.2, 0.0});  // beside the paddles
  world.step();
  EXPECT_FALSE(world.gripper(rig.gripper_id).inner_beam);
  EXPECT_EQ(world.gripper(rig.gripper_id).paddles, GripperPaddles::open);
  EXPECT_NEAR(world.gripper(rig.gripper_id).time, world.time(), 1e-12);
}

TEST(Gripper, ClosingPicksUpTheNearestAndItIsCarriedUntilPutDown) {
  GripperRig rig = gripper_rig();
  World& world = rig.world;
  const ModelId far = add_puck(world, "far", 0.39, 0.0);
  const ModelId near = add_puck(world, "near", 0.35, 0.02);
  add_puck(world, "box", 0.32, 0.0, false);  // nearer, but not grippable
  world.close_gripper(rig.gripper_id);
  EXPECT_EQ(world.gripper(rig.gripper_id).paddles, GripperPaddles::closed);
  EXPECT_EQ(world.gripper(rig.gripper_id).carried, 1);
  EXPECT_TRUE(world.gripper(rig.gripper_id).inner_beam);
  // The carried puck is part of the robot's tree now: its own sensors and
  // collisions ignore it.
  EXPECT_EQ(world.scene().model(near).root, rig.robot_id);
  EXPECT_EQ(world.scene().model(far).root, far);

  world.command_velocity(rig.robot_id, {0.5, 0.0, 0.4});
  run(world, 10);
  expect_pose_near(world.true_pose(near), world.true_pose(rig.gripper_id).compose({0.1, 0.02, 0.0}));
  expect_pose_near(world.true_pose(far), {0.39, 0.0, 0.0});

  world.open_gripper(rig.gripper_id);
  const geometry::Pose2 put_down = world.true_pose(near);
  EXPECT_EQ(world.gripper(rig.gripper_id).carried, 0);
  EXPECT_EQ(world.gripper(rig.gripper_id).paddles, GripperPaddles::open);
  EXPECT_EQ(world.scene().model(near).root, near);
  run(world, 10);
  EXPECT_EQ(world.true_pose(near), put_down);
}

TEST(Gripper, AFullGripperTakesNoMore) {
  GripperRig rig = gripper_rig();
  World& world = rig.world;
  const ModelId first = add_puck(world, "first", 0.32, 0.0);
  const ModelId second = add_puck(world, "second", 0.38, 0.0);
  world.close_gripper(rig.gripper_id);
  world.close_gripper(rig.gripper_id);
  EXPECT_EQ(world.gripper(rig.gripper_id).carried, 1);
  EXPECT_EQ(world.scene().model(first).root, rig.robot_id);
  EXPECT_EQ(world.scene().model(second).root, second);
}

TEST(Gripper, AConsumingGripperMakesWhatItTakesVanish) {
  GripperRig rig = gripper_rig({.consume = true});
  World& world = rig.world;
  const ModelId first = add_puck(world, "first", 0.32, 0.0);
  const ModelId second = add_puck(world, "second", 0.38, 0.0);
  world.close_gripper(rig.gripper_id);
  world.open_gripper(rig.gripper_id);
  world.close_gripper(rig.gripper_id);
  EXPECT_EQ(world.gripper(rig.gripper_id).carried, 2);
  EXPECT_FALSE(world.scene().model(first).present);
  EXPECT_FALSE(world.scene().model(second).present);
  EXPECT_FALSE(world.gripper(rig.gripper_id).inner_beam);
  // Gone from rays too.
  EXPECT_EQ(world.scene().cast({0.32, 1.0}, -std::numbers::pi / 2, 5.0, rig.robot_id).model, kNoModel);
}

TEST(Gripper, TeleportingACarriedModelTakesItOutOfTheGripper) {
  GripperRig rig = gripper_rig();
  World& world = rig.world;
  const ModelId puck = add_puck(world, "puck", 0.35, 0.0);
  world.close_gripper(rig.gripper_id);
  world.set_true_pose(puck, {4.0, 4.0, 0.0});
  world.step();
  EXPECT_EQ(world.gripper(rig.gripper_id).carried, 0);
  world.command_velocity(rig.robot_id, {0.5, 0.0, 0.0});
  run(world, 4);
  expect_pose_near(world.true_pose(puck), {4.0, 4.0, 0.0});
}

}  // namespace playerkit::sim::gripper_test
