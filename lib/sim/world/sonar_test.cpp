#include "sim/world/sonar.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/world/sensor_test_support.hpp"

namespace playerkit::sim::sonar_test {

using namespace sensor_test_support;
using geometry::Pose2;
constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

// A Pioneer 2-DX's 16 sonars (x, y in mm, heading in degrees; the table of
// lib/families/p2os/protocol/robot_params.cpp).
std::vector<Pose2> pioneer_ring() {
  const double poses[16][3] = {{115, 130, 90},    {155, 115, 50},   {190, 80, 30},    {210, 25, 10},
                               {210, -25, -10},   {190, -80, -30},  {155, -115, -50}, {115, -130, -90},
                               {-115, -130, -90}, {-155, -115, -130}, {-190, -80, -150}, {-210, -25, -170},
                               {-210, 25, 170},   {-190, 80, 150},  {-155, 115, 130}, {-115, 130, 90}};
  std::vector<Pose2> ring;
  for (const auto& p : poses) ring.push_back({p[0] / 1000.0, p[1] / 1000.0, p[2] * kDegree});
  return ring;
}

// A room with a wall block, the sonar's robot (a disc around the ring,
// which the rays must pass through) and unrelated bodies, one of them
// invisible to rangers.
struct Room {
  Scene scene;
  ModelId robot = kNoModel;
  ModelId sonar_model = kNoModel;
  ModelId near_box = kNoModel;
  ModelId far_disc = kNoModel;
  ModelId see_through = kNoModel;

  Room() : scene(make_map()) {
    robot = add_model(scene, {0.5, 0.2, 0.3}, disc(0.5));
    sonar_model = add_model(scene, {0.5, 0.2, 0.3}, no_body(), {}, {}, robot);
    near_box = add_model(scene, {1.2, 0.6, 0.7}, box(0.4, 0.25));
    far_disc = add_model(scene, {0.13, 1.8, 0.0}, disc(0.6));
    see_through = add_model(scene, {0.5, -0.6, 0.0}, box(1.2, 0.3), {.ranger = -1.0});
  }

  static grid::OccupancyGrid make_map() {
    grid::OccupancyGrid map = room();
    add_wall(map, -2.0, -2.0, 2.0, -1.8);
    return map;
  }
};

TEST(Sonar, RangesMatchAnIndependentRayMarchFromEachTransducer) {
  const Room room;
  const SonarSpec spec{.transducers = pioneer_ring(), .range_max = 5.0};
  const Pose2 model_pose{0.5, 0.2, 0.3};
  NoiseDraws noise(1, room.sonar_model, 0);
  const SonarScan scan = scan_sonar(room.scene, spec, model_pose, room.robot, noise);

  ASSERT_EQ(scan.ranges.size(), 16u);
  std::vector<int> hits_per_model(room.scene.models().size(), 0);
  int walls = 0, crossing_the_invisible_box = 0;
  for (std::size_t i = 0; i < 16; ++i) {
    const Pose2& t = spec.transducers[i];
    // The transducer's global pose, worked out here by hand.
    const double c = std::cos(model_pose.yaw), s = std::sin(model_pose.yaw);
    const Eigen::Vector2d origin{model_pose.x + c * t.x - s * t.y, model_pose.y + s * t.x + c * t.y};
    const MarchedHit expected = march(room.scene, origin, model_pose.yaw + t.yaw, 5.0, room.robot, ranger_stops);
    EXPECT_NEAR(scan.ranges[i], expected.range, kMarchStep + 1e-9) << "transducer " << i;
    if (expected.model != kNoModel) ++hits_per_model[static_cast<std::size_t>(expected.model)];
    else if (expected.range < 5.0) ++walls;
    const MarchedHit unfiltered = march(room.scene, origin, model_pose.yaw + t.yaw, 5.0, room.robot, any_body_stops);
    if (unfiltered.model == room.see_through) ++crossing_the_invisible_box;
  }
  EXPECT_GT(crossing_the_invisible_box, 0);
  EXPECT_GT(hits_per_model[static_cast<std::size_t>(room.near_box)], 0);
  EXPECT_GT(hits_per_model[static_cast<std::size_t>(room.far_disc)], 0);
  EXPECT_EQ(hits_per_model[static_cast<std::size_t>(room.see_through)], 0);
  EXPECT_GT(walls, 0);
}

TEST(Sonar, ShortReadingsAreRaisedToRangeMinAndMissesReadRangeMax) {
  Scene scene(room());
  const ModelId robot = add_model(scene, {}, disc(0.4));
  add_model(scene, {0.3, 0.0, 0.0}, box(0.1, 1.0));  // its near face 0.25 m ahead
  const SonarSpec spec{.transducers = {{0.0, 0.0, 0.0}, {0.0, 0.0, kPi / 2.0}}, .range_min = 0.4, .range_max = 3.0};
  NoiseDraws noise(1, 1, 0);
  const SonarScan scan = scan_sonar(scene, spec, {}, robot, noise);
  ASSERT_EQ(scan.ranges.size(), 2u);
  EXPECT_EQ(scan.ranges[0], 0.4);
  EXPECT_EQ(scan.ranges[1], 3.0);  // the room's wall is 4.95 m away

  const SonarSpec short_min{.transducers = spec.transducers, .range_min = 0.1, .range_max = 3.0};
  const SonarScan unraised = scan_sonar(scene, short_min, {}, robot, noise);
  EXPECT_NEAR(unraised.ranges[0], 0.25, 1e-9);
}

TEST(Sonar, NoTransducersGiveAnEmptyScan) {
  const Room room;
  NoiseDraws noise(1, 1, 0);
  EXPECT_TRUE(scan_sonar(room.scene, {}, {}, room.robot, noise).ranges.empty());
}

// 32 transducers at one point, all facing the flat face of a wall 2 m
// ahead (the cells from x = 2.0 on) at bearings within ±30°.
struct WallAhead {
  Scene scene;
  ModelId robot = kNoModel;
  SonarSpec spec;
  WallAhead(double noise_sd, double range_max) : scene(make_map()) {
    robot = add_model(scene, {}, disc(0.4));
    for (int i = 0; i < 32; ++i) spec.transducers.push_back({0.0, 0.0, (-30.0 + 60.0 * i / 31.0) * kDegree});
    spec.noise_sd = noise_sd;
    spec.range_max = range_max;
  }
  static grid::OccupancyGrid make_map() {
    grid::OccupancyGrid map = room();
    add_wall(map, 2.0, -4.0, 2.2, 4.0);
    return map;
  }
  double clean_range(std::size_t i) const { return 2.0 / std::cos(spec.transducers[i].yaw); }
};

TEST(Sonar, GaussianNoiseHasTheConfiguredStandardDeviation) {
  const WallAhead wall(0.03, 5.0);
  std::vector<double> errors;
  for (std::uint64_t step = 0; step < 250; ++step) {
    NoiseDraws noise(77, 4, step);
    const SonarScan scan = scan_sonar(wall.scene, wall.spec, {}, wall.robot, noise);
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) errors.push_back(scan.ranges[i] - wall.clean_range(i));
  }
  ASSERT_EQ(errors.size(), 8000u);
  const auto [mean, sd] = mean_and_sd(errors);
  EXPECT_NEAR(mean, 0.0, 3.0 * 0.03 / std::sqrt(8000.0));
  EXPECT_NEAR(sd, 0.03, 0.03 * 0.04);
}

TEST(Sonar, NoiseFreeWithoutNoiseAndAtRangeMax) {
  const WallAhead exact(0.0, 5.0);
  NoiseDraws noise(77, 4, 0);
  const SonarScan scan = scan_sonar(exact.scene, exact.spec, {}, exact.robot, noise);
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) EXPECT_NEAR(scan.ranges[i], exact.clean_range(i), 1e-9);

  // range_max short of the wall: every reading is range_max, however noisy.
  const WallAhead beyond(0.5, 1.5);
  for (std::uint64_t step = 0; step < 20; ++step) {
    NoiseDraws draws(77, 4, step);
    for (const double range : scan_sonar(beyond.scene, beyond.spec, {}, beyond.robot, draws).ranges) {
      EXPECT_EQ(range, 1.5);
    }
  }
}

TEST(Sonar, TheSameDrawsGiveTheSameScanAndOtherStepsAnother) {
  const WallAhead wall(0.03, 5.0);
  NoiseDraws first(3, 4, 100), again(3, 4, 100), later(3, 4, 101);
  const SonarScan a = scan_sonar(wall.scene, wall.spec, {}, wall.robot, first);
  EXPECT_EQ(a.ranges, scan_sonar(wall.scene, wall.spec, {}, wall.robot, again).ranges);
  EXPECT_NE(a.ranges, scan_sonar(wall.scene, wall.spec, {}, wall.robot, later).ranges);
}

}  // namespace playerkit::sim::sonar_test
