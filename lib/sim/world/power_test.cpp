#include <gtest/gtest.h>

#include "sim/world/world.hpp"
#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::power_test {

using world_test_support::fill_walls;
using world_test_support::mounted;
using world_test_support::open_floor;
using world_test_support::robot;
using world_test_support::run;

struct Battery {
  World world;
  ModelId robot_id;
  ModelId power_id;
};

Battery battery(PowerSpec spec, grid::OccupancyGrid map = open_floor()) {
  Battery setup{World({.step = 0.1}, std::move(map)), kNoModel, kNoModel};
  setup.robot_id = setup.world.add(robot("r0", {}));
  setup.power_id = setup.world.add(mounted(setup.robot_id, spec));
  setup.world.set_active(setup.robot_id, true);
  setup.world.set_active(setup.power_id, true);
  return setup;
}

PowerSpec hundred_joules() {
  return {.capacity_joules = 100.0, .idle_watts = 1.0, .watts_per_mps = 20.0, .full_volts = 13.0,
          .empty_volts = 10.0, .interval = 1.0};
}

TEST(Power, IdleDrainAtItsInterval) {
  auto [world, robot_id, power_id] = battery(hundred_joules());
  world.step();
  EXPECT_NEAR(world.power(power_id).joules, 99.9, 1e-9);
  EXPECT_NEAR(world.power(power_id).volts, 10.0 + 3.0 * 0.999, 1e-9);
  EXPECT_NEAR(world.power(power_id).time, 0.1, 1e-12);
  run(world, 9);
  EXPECT_NEAR(world.power(power_id).time, 0.1, 1e-12);  // one reading a second
  world.step();
  EXPECT_NEAR(world.power(power_id).joules, 98.9, 1e-9);
  EXPECT_NEAR(world.power(power_id).time, 1.1, 1e-12);
}

TEST(Power, MovingDrainsMorePerMetrePerSecond) {
  auto [world, robot_id, power_id] = battery(hundred_joules());
  world.command_velocity(robot_id, {0.5, 0.0, 0.0});
  run(world, 11);
  // 11 steps of 0.1 s at 1 W + 20 W per m/s x 0.5 m/s = 11 W.
  EXPECT_NEAR(world.power(power_id).joules, 100.0 - 11.0 * 1.1, 1e-9);
}

TEST(Power, AStalledRobotDrainsOnlyItsIdleWatts) {
  grid::OccupancyGrid map = open_floor();
  fill_walls(map, 0.2, -1.0, 1.0, 1.0);  // touching the robot's front
  auto [world, robot_id, power_id] = battery(hundred_joules(), map);
  world.command_velocity(robot_id, {0.5, 0.0, 0.0});
  run(world, 11);
  EXPECT_TRUE(world.position(robot_id).stalled);
  EXPECT_NEAR(world.power(power_id).joules, 100.0 - 1.1, 1e-9);
}

TEST(Power, AnEmptyBatteryReadsZeroJoulesAndEmptyVolts) {
  PowerSpec spec = hundred_joules();
  spec.capacity_joules = 1.0;
  auto [world, robot_id, power_id] = battery(spec);
  run(world, 31);
  EXPECT_EQ(world.power(power_id).joules, 0.0);
  EXPECT_EQ(world.power(power_id).volts, 10.0);
}

}  // namespace playerkit::sim::power_test
