#include "sim/world/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "sim/world/world_test_support.hpp"

namespace playerkit::sim::world_test {

using world_test_support::mounted;
using world_test_support::object;
using world_test_support::open_floor;
using world_test_support::robot;
using world_test_support::run;
using world_test_support::walled_floor;

template <typename Call>
std::string model_error_of(Call&& call) {
  try {
    call();
  } catch (const ModelError& error) {
    return error.what();
  }
  return "(no ModelError)";
}

TEST(World, GeneratedNamesCountEarlierSiblingsOfTheTypeUnderTheParentsName) {
  World world({}, open_floor());
  ModelSpec position;
  position.type = "position";
  position.params = PositionSpec{};
  const ModelId first = world.add(position);
  const ModelId second = world.add(position);
  const ModelId box = world.add(ModelSpec{});
  const ModelId laser = world.add(mounted(first, LaserSpec{}));
  const ModelId sonar = world.add(mounted(first, SonarSpec{}));
  const ModelId other_laser = world.add(mounted(first, LaserSpec{}));
  EXPECT_EQ(world.spec(first).name, "position:0");
  EXPECT_EQ(world.spec(second).name, "position:1");
  EXPECT_EQ(world.spec(box).name, "model:0");
  EXPECT_EQ(world.spec(box).type, "model");
  EXPECT_EQ(world.spec(laser).name, "position:0.laser:0");
  EXPECT_EQ(world.spec(sonar).name, "position:0.sonar:0");
  EXPECT_EQ(world.spec(other_laser).name, "position:0.laser:1");
  EXPECT_EQ(world.find("position:0.laser:1"), other_laser);
  EXPECT_EQ(world.find("nothing"), std::nullopt);
  EXPECT_EQ(world.children(first), (std::vector<ModelId>{laser, sonar, other_laser}));
  EXPECT_EQ(world.root_of(other_laser), first);
  EXPECT_EQ(world.root_of(second), second);
  EXPECT_EQ(world.size(), 6u);
  // A name given explicitly that a generated one would repeat is skipped.
  ModelSpec taken;
  taken.name = "model:1";
  world.add(taken);
  EXPECT_EQ(world.spec(world.add(ModelSpec{})).name, "model:2");
}

TEST(World, BadIdsKindsNamesAndParentsAreModelErrorsNamingTheModel) {
  World world({}, open_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  const ModelId laser = world.add(mounted(r0, LaserSpec{}));
  EXPECT_EQ(model_error_of([&] { (void)world.laser(r0); }), "model 0 (\"r0\") is a position, not a laser");
  EXPECT_EQ(model_error_of([&] { world.command_velocity(laser, {}); }),
            "model 1 (\"r0.laser:0\") is a laser, not a position");
  EXPECT_EQ(model_error_of([&] { (void)world.position(7); }), "no model 7 (the world has 2 models)");
  EXPECT_EQ(model_error_of([&] { world.set_active(-1, true); }), "no model -1 (the world has 2 models)");
  EXPECT_EQ(model_error_of([&] { world.add(robot("r0", {})); }), "model \"r0\": the name is taken by model 0");
  EXPECT_EQ(model_error_of([&] { world.add(mounted(9, SonarSpec{})); }),
            "model \"\": its parent 9 does not exist");
  EXPECT_EQ(model_error_of([&] { world.set_true_pose(laser, {}); }),
            "model 1 (\"r0.laser:0\") rides on model 0; only a top-level model can be moved");
  EXPECT_EQ(world.size(), 2u);
  EXPECT_THROW(world.configure_laser(laser, 0.0, 10), std::invalid_argument);
  EXPECT_THROW(world.command_velocity(r0, {NAN, 0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(World({.step = 0.0}, open_floor()), std::invalid_argument);
}

TEST(World, SensorsReadAtTheirIntervalFromTheFirstStepAfterActivation) {
  World world({.step = 0.1}, walled_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  LaserSpec spec;
  spec.interval = 0.2;
  spec.samples = 1;
  const ModelId laser = world.add(mounted(r0, spec));
  world.step();
  EXPECT_TRUE(world.laser(laser).ranges.empty());  // nobody asked
  world.set_active(laser, true);
  const double expected_times[] = {0.2, 0.2, 0.4, 0.4, 0.6};
  for (const double expected : expected_times) {
    world.step();
    EXPECT_NEAR(world.laser(laser).time, expected, 1e-12);
  }
  world.set_active(laser, false);
  run(world, 3);
  EXPECT_NEAR(world.laser(laser).time, 0.6, 1e-12);  // the last reading stays
}

TEST(World, SensorsLookFromTheirMountPoseAndMoveWithTheRobot) {
  World world({.step = 0.1}, walled_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  LaserSpec laser_spec;
  laser_spec.samples = 1;
  laser_spec.pose = {0.1, 0.0, 0.0};
  const ModelId laser = world.add(mounted(r0, laser_spec, {0.05, 0.0, 0.0}));
  SonarSpec sonar_spec;
  sonar_spec.transducers = {{0.2, 0.0, 0.0}, {0.0, 0.2, std::numbers::pi / 2}};
  const ModelId sonar = world.add(mounted(r0, sonar_spec));
  for (const ModelId id : {r0, laser, sonar}) world.set_active(id, true);
  world.step();
  ASSERT_EQ(world.laser(laser).ranges.size(), 1u);
  EXPECT_NEAR(world.laser(laser).ranges[0], 2.05 - 0.15, 1e-9);
  ASSERT_EQ(world.sonar(sonar).ranges.size(), 2u);
  EXPECT_NEAR(world.sonar(sonar).ranges[0], 2.05 - 0.2, 1e-9);
  EXPECT_EQ(world.sonar(sonar).ranges[1], sonar_spec.range_max);
  world.command_velocity(r0, {0.5, 0.0, 0.0});
  run(world, 2);
  EXPECT_NEAR(world.laser(laser).ranges[0], 2.05 - 0.15 - 0.1, 1e-9);
}

// Three robots driving about with noisy lasers.
struct NoisyWorld {
  World world;
  std::vector<ModelId> lasers;
};

NoisyWorld noisy_world(std::uint64_t seed, int laser_activation_step) {
  NoisyWorld setup{World({.step = 0.1, .seed = seed}, walled_floor()), {}};
  LaserSpec spec;
  spec.samples = 31;
  spec.noise_sd = 0.05;
  spec.interval = 0.1;
  for (int i = 0; i < 3; ++i) {
    const ModelId id = setup.world.add(robot("r" + std::to_string(i), {0.0, -2.0 + 2.0 * i, 0.3 * i}));
    setup.world.set_active(id, true);
    setup.world.command_velocity(id, {0.2, 0.0, 0.1 * (i - 1)});
    setup.lasers.push_back(setup.world.add(mounted(id, spec)));
  }
  for (int step = 0; step < 10; ++step) {
    if (step == laser_activation_step) {
      for (const ModelId laser : setup.lasers) setup.world.set_active(laser, true);
    }
    setup.world.step();
  }
  return setup;
}

bool same_scans(const NoisyWorld& a, const NoisyWorld& b) {
  for (std::size_t i = 0; i < a.lasers.size(); ++i) {
    if (a.world.laser(a.lasers[i]).ranges != b.world.laser(b.lasers[i]).ranges) return false;
  }
  return true;
}

TEST(World, TheSameSeedAndCallsGiveTheSameReadingsAndAnotherSeedOthers) {
  const NoisyWorld first = noisy_world(5, 0);
  const NoisyWorld again = noisy_world(5, 0);
  const NoisyWorld other = noisy_world(6, 0);
  ASSERT_EQ(first.world.laser(first.lasers[0]).ranges.size(), 31u);
  EXPECT_TRUE(same_scans(first, again));
  EXPECT_FALSE(same_scans(first, other));
  for (std::size_t i = 0; i < first.lasers.size(); ++i) {
    EXPECT_EQ(first.world.true_pose(first.lasers[i]), other.world.true_pose(other.lasers[i]));  // noise only
  }
}

TEST(World, ASensorSwitchedOnLateReadsWhatOneOnAllAlongReads) {
  const NoisyWorld all_along = noisy_world(5, 0);
  const NoisyWorld late = noisy_world(5, 8);
  EXPECT_NEAR(late.world.laser(late.lasers[0]).time, 1.0, 1e-12);
  EXPECT_TRUE(same_scans(all_along, late));
}

TEST(World, ATeleportMovesTheModelAndEverythingOnIt) {
  World world({}, open_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  const ModelId laser = world.add(mounted(r0, LaserSpec{}, {0.1, 0.2, 0.3}));
  world.set_true_pose(r0, {3.0, -1.0, 4.0});
  const geometry::Pose2 expected = geometry::Pose2{3.0, -1.0, 4.0}.compose({0.1, 0.2, 0.3});
  EXPECT_NEAR(world.true_pose(laser).x, expected.x, 1e-12);
  EXPECT_NEAR(world.true_pose(laser).y, expected.y, 1e-12);
  EXPECT_NEAR(world.true_pose(laser).yaw, expected.yaw, 1e-12);
  EXPECT_NEAR(world.true_pose(r0).yaw, 4.0 - 2.0 * std::numbers::pi, 1e-12);  // normalised
  EXPECT_EQ(world.scene().model(laser).pose, world.true_pose(laser));
}

TEST(World, PtzCommandsAreClampedToThePanLimitAndTheZoomRange) {
  World world({}, open_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  const ModelId ptz = world.add(mounted(r0, PtzSpec{}));
  world.set_active(ptz, true);
  world.step();
  EXPECT_NEAR(world.ptz(ptz).fov, std::numbers::pi / 3, 1e-12);  // starts zoomed out
  world.command_ptz(ptz, 3.0, 0.5, 0.001);
  world.step();
  EXPECT_NEAR(world.ptz(ptz).pan, 100.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_EQ(world.ptz(ptz).tilt, 0.0);
  EXPECT_NEAR(world.ptz(ptz).fov, std::numbers::pi / 36, 1e-12);
  world.command_ptz(ptz, -3.0, 0.0, 5.0);
  world.step();
  EXPECT_NEAR(world.ptz(ptz).pan, -100.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(world.ptz(ptz).fov, std::numbers::pi / 3, 1e-12);
  world.command_ptz(ptz, 0.25, 0.0, 0.5);
  world.step();
  EXPECT_NEAR(world.ptz(ptz).pan, 0.25, 1e-12);
  EXPECT_NEAR(world.ptz(ptz).fov, 0.5, 1e-12);
}

TEST(World, ABlobfinderOnAPtzLooksWhereThePtzPans) {
  World world({}, open_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  const ModelId ptz = world.add(mounted(r0, PtzSpec{}));
  const ModelId camera = world.add(mounted(ptz, BlobfinderSpec{}));
  world.add(object("red box", {0.0, 3.0, 0.0}, Shape::rectangle, 0.5, 0.5));  // to the robot's left
  world.set_active(camera, true);
  world.step();
  EXPECT_TRUE(world.blobs(camera).blobs.empty());
  world.command_ptz(ptz, std::numbers::pi / 2, 0.0, std::numbers::pi / 3);
  world.step();
  ASSERT_EQ(world.blobs(camera).blobs.size(), 1u);
  EXPECT_EQ(world.blobs(camera).blobs[0].color, (Rgb{255, 0, 0}));
  EXPECT_NEAR(world.blobs(camera).blobs[0].range, 2.75, 0.05);
}

TEST(World, AFiducialFinderOnALaserLooksFromTheScanOrigin) {
  World world({}, open_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  LaserSpec laser_spec;
  laser_spec.pose = {0.5, 0.0, 0.0};
  const ModelId laser = world.add(mounted(r0, laser_spec));
  const ModelId finder = world.add(mounted(laser, FiducialSpec{}));
  ModelSpec beacon = object("beacon", {3.0, 0.0, 0.0}, Shape::rectangle, 0.1, 0.1);
  beacon.returns.fiducial_id = 7;
  const ModelId target = world.add(beacon);
  world.set_active(finder, true);
  world.step();
  ASSERT_EQ(world.fiducials(finder).sightings.size(), 1u);
  const FiducialSighting& seen = world.fiducials(finder).sightings[0];
  EXPECT_EQ(seen.id, 7);
  EXPECT_EQ(seen.model, target);
  EXPECT_NEAR(seen.range, 2.5, 1e-9);
}

TEST(World, ConfiguringALaserLastsUntilItIsSwitchedOff) {
  World world({}, open_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  const ModelId laser = world.add(mounted(r0, LaserSpec{}));
  world.set_active(laser, true);
  world.configure_laser(laser, std::numbers::pi / 2, 91);
  world.step();
  EXPECT_EQ(world.laser(laser).ranges.size(), 91u);
  EXPECT_NEAR(world.laser(laser).max_angle, std::numbers::pi / 4, 1e-12);
  world.set_active(laser, false);  // Stage 1.3 resets the scan then
  world.set_active(laser, true);
  world.step();
  EXPECT_EQ(world.laser(laser).ranges.size(), 361u);
}

TEST(World, AMovedWorldKeepsRunning) {
  World world({.step = 0.1}, open_floor());
  const ModelId r0 = world.add(robot("r0", {}));
  world.set_active(r0, true);
  world.command_velocity(r0, {1.0, 0.0, 0.0});
  World moved = std::move(world);
  run(moved, 3);
  EXPECT_NEAR(moved.true_pose(r0).x, 0.3, 1e-12);
  EXPECT_EQ(moved.steps(), 3u);
  EXPECT_NEAR(moved.time(), 0.3, 1e-12);
}

}  // namespace playerkit::sim::world_test
