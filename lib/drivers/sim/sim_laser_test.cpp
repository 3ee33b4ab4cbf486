// gazebo.md §6's laser check (a wall 2 m ahead) and Stage 1.3's SET_CONFIG
// rules (stage-worlds.md §3.5), on a world made here.
#include <gtest/gtest.h>

#include <cmath>

#include "drivers/sim/sim_test_support.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::drivers::sim {
namespace sim_laser_test {

using namespace testing;
using protocol::kLaserCode;
using protocol::LaserConfig;
using protocol::LaserData;

// A wall whose face is 2 m ahead of the robot, 10 m wide; `samples` over 180°.
World wall_world(int samples = 181) {
  grid::OccupancyGrid map = open_floor();
  add_wall(map, 2.0, -5.0, 2.5, 5.0);
  World world({.step = 0.1, .seed = 1}, std::move(map));
  const ModelId robot = world.add(test_robot("robot"));
  world.add(on(robot, "robot.laser", test_laser(samples)));
  return world;
}

// Where a beam at `bearing` (rad) from the robot meets the wall's face.
double range_to_wall(double bearing) { return 2.0 / std::cos(bearing); }

struct LaserFixture : ::testing::Test {
  void load(int samples = 181) {
    sim = std::make_unique<SimDevices>(wall_world(samples));
    sim->load("laser:0 ( driver \"laser\" model \"robot.laser\" )\n");
    ASSERT_TRUE(laser().subscribe());
  }
  core::Device& laser() { return sim->device(kLaserCode); }
  LaserData scan() {
    sim->step();
    sim->cycle(laser());
    return sim->latest<LaserData>(laser());
  }
  core::Reply set_config(int min_angle, int max_angle, int resolution, int range_res = 1) {
    LaserConfig config;
    config.subtype = protocol::kLaserSetConfig;
    config.min_angle = static_cast<std::int16_t>(min_angle);
    config.max_angle = static_cast<std::int16_t>(max_angle);
    config.resolution = static_cast<std::uint16_t>(resolution);
    config.range_res = static_cast<std::uint16_t>(range_res);
    config.intensity = 1;
    return sim->ask(laser(), protocol::encode(config));
  }
  std::unique_ptr<SimDevices> sim;
};

TEST_F(LaserFixture, AWallTwoMetresAheadReadsTwoMetresOverCosineOfTheBearing) {
  load();
  const LaserData data = scan();
  EXPECT_EQ(data.range_count, 181);
  EXPECT_EQ(data.min_angle, -9000);
  EXPECT_EQ(data.max_angle, 9000);
  EXPECT_EQ(data.resolution, 100);
  EXPECT_EQ(data.range_res, 1);  // 8 m fits 16 bits of mm
  EXPECT_NEAR(data.ranges[90], 2000, kCell * 1000);
  // While the beam meets the wall (|bearing| < atan(5/2) = 68°), within a map cell.
  for (int beam = 30; beam <= 150; ++beam) {
    const double bearing = (beam - 90) * std::numbers::pi / 180.0;
    EXPECT_NEAR(data.ranges[static_cast<std::size_t>(beam)], 1000 * range_to_wall(bearing),
                1000 * kCell / std::cos(bearing) + 1)
        << "beam " << beam;
  }
  // Sideways nothing is near: the range is the maximum.
  EXPECT_EQ(data.ranges[0], 8000);
  EXPECT_EQ(laser().latest_data()->timestamp, (protocol::Timestamp{0, 100000}));
}

TEST_F(LaserFixture, GetConfigDescribesTheScanServed) {
  load();
  const core::Reply reply = sim->ask(laser(), {protocol::kLaserGetConfig});
  ASSERT_EQ(reply.type, protocol::MessageType::kAck);
  const auto config = protocol::decode<LaserConfig>(reply.payload);
  EXPECT_EQ(config.subtype, protocol::kLaserGetConfig);
  EXPECT_EQ(config.min_angle, -9000);
  EXPECT_EQ(config.max_angle, 9000);
  EXPECT_EQ(config.resolution, 100);
  EXPECT_EQ(config.range_res, 1);
}

TEST_F(LaserFixture, SetConfigRecomputesTheSamples) {
  load();
  ASSERT_EQ(set_config(-9000, 9000, 50).type, protocol::MessageType::kAck);
  LaserData data = scan();
  EXPECT_EQ(data.range_count, 361);
  EXPECT_EQ(data.resolution, 50);
  EXPECT_NEAR(data.ranges[180], 2000, kCell * 1000);

  ASSERT_EQ(set_config(-5000, 5000, 25).type, protocol::MessageType::kAck);
  data = scan();
  EXPECT_EQ(data.range_count, 401);
  EXPECT_EQ(data.min_angle, -5000);
  EXPECT_EQ(data.max_angle, 5000);
  EXPECT_NEAR(data.ranges[200], 2000, kCell * 1000);

  const auto config = protocol::decode<LaserConfig>(sim->ask(laser(), {protocol::kLaserGetConfig}).payload);
  EXPECT_EQ(config.resolution, 25);
  EXPECT_EQ(config.min_angle, -5000);
}

TEST_F(LaserFixture, AnAsymmetricScanServesItsPart) {
  load();
  ASSERT_EQ(set_config(-3000, 9000, 100).type, protocol::MessageType::kAck);
  const LaserData data = scan();
  EXPECT_EQ(data.range_count, 121);
  EXPECT_EQ(data.min_angle, -3000);
  EXPECT_EQ(data.max_angle, 9000);
  EXPECT_NEAR(data.ranges[30], 2000, kCell * 1000);  // straight ahead
  const double bearing = -30 * std::numbers::pi / 180.0;
  EXPECT_NEAR(data.ranges[0], 1000 * range_to_wall(bearing), 1000 * kCell / std::cos(bearing) + 1);
}

TEST_F(LaserFixture, SetConfigOutsideStage13sRulesIsRefused) {
  load();
  EXPECT_EQ(set_config(-9000, 9000, 25).type, protocol::MessageType::kNack);   // 0.25° reaches ±50° only
  EXPECT_EQ(set_config(-9000, 9000, 30).type, protocol::MessageType::kNack);   // no such resolution
  EXPECT_EQ(set_config(-18100, 0, 100).type, protocol::MessageType::kNack);    // past ±180°
  EXPECT_EQ(set_config(1000, -1000, 100).type, protocol::MessageType::kNack);  // backwards
  EXPECT_EQ(set_config(-9000, 9000, 100, 7).type, protocol::MessageType::kNack);
  EXPECT_EQ(sim->ask(laser(), {protocol::kLaserSetConfig, 0}).type, protocol::MessageType::kNack);  // short
  // The scan is as it was.
  EXPECT_EQ(scan().range_count, 181);
}

TEST_F(LaserFixture, TheRangeUnitOfSetConfigIsHonoured) {
  load();
  ASSERT_EQ(set_config(-9000, 9000, 100, 10).type, protocol::MessageType::kAck);
  const LaserData data = scan();
  EXPECT_EQ(data.range_res, 10);
  EXPECT_NEAR(data.ranges[90], 200, kCell * 100);  // cm
}

TEST_F(LaserFixture, TheLastUnsubscriptionResetsTheScan) {
  load();
  ASSERT_EQ(set_config(-5000, 5000, 25).type, protocol::MessageType::kAck);
  laser().unsubscribe();
  ASSERT_TRUE(laser().subscribe());
  EXPECT_EQ(scan().range_count, 181);
}

TEST_F(LaserFixture, MoreSamplesThanPlayerCarriesAreThinnedToFit) {
  load(1081);  // 1/6° over 180°
  const LaserData data = scan();
  EXPECT_EQ(data.range_count, 361);  // every third
  EXPECT_EQ(data.resolution, 50);
  EXPECT_EQ(data.min_angle, -9000);
  EXPECT_EQ(data.max_angle, 9000);
  EXPECT_NEAR(data.ranges[180], 2000, kCell * 1000);
}

TEST_F(LaserFixture, GeometryIsTheScanOriginOnTheRobot) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot", {3.0, 1.0, 1.0}));
  ModelSpec laser_model = on(robot, "robot.laser", test_laser(), {0.1, -0.05, 0.0});
  laser_model.body.present = true;
  laser_model.body.size = {0.155, 0.155};
  std::get<LaserSpec>(laser_model.params).pose = {0.02, 0.0, std::numbers::pi / 2};
  world.add(laser_model);
  sim = std::make_unique<SimDevices>(std::move(world));
  sim->load("laser:0 ( driver \"gz_laser\" gz_id \"robot\" )\n");  // found on the robot
  ASSERT_TRUE(laser().subscribe());
  const core::Reply reply = sim->ask(laser(), {protocol::kLaserGetGeom});
  ASSERT_EQ(reply.type, protocol::MessageType::kAck);
  const auto geom = protocol::decode<protocol::LaserGeom>(reply.payload);
  EXPECT_EQ(geom.pose, (std::array<std::int16_t, 3>{120, -50, 90}));
  EXPECT_EQ(geom.size, (std::array<std::int16_t, 2>{155, 155}));
}

}  // namespace sim_laser_test
}  // namespace playerkit::drivers::sim
