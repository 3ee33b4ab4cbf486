#include "sim/world/laser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/world/sensor_test_support.hpp"

namespace playerkit::sim::laser_test {

using namespace sensor_test_support;
using geometry::Pose2;
constexpr double kPi = std::numbers::pi;

// A room with an inner wall, the laser's own robot at the origin (a disc
// around the scan origin and a box riding on it), and unrelated bodies: a
// turned box, a disc, a box rangers see through and a bright one.
struct Room {
  Scene scene;
  ModelId robot = kNoModel;
  ModelId turned_box = kNoModel;
  ModelId disc_model = kNoModel;
  ModelId see_through = kNoModel;
  ModelId bright = kNoModel;

  Room() : scene(make_map()) {
    robot = add_model(scene, {0.0, 0.0, 0.4}, disc(0.5));
    add_model(scene, {0.1, 0.0, 0.4}, box(0.15, 0.15), {}, {}, robot);
    turned_box = add_model(scene, {2.0, 1.0, 0.3}, box(0.5, 0.3));
    disc_model = add_model(scene, {-1.5, 2.0, 0.0}, disc(0.4));
    see_through = add_model(scene, {0.0, -2.0, 0.0}, box(1.0, 0.2), {.ranger = -1.0});
    bright = add_model(scene, {0.6, -1.5, 1.0}, box(0.3, 0.6), {.laser_bright = true});
  }

  static grid::OccupancyGrid make_map() {
    grid::OccupancyGrid map = room();
    add_wall(map, 1.0, -3.0, 1.2, -0.5);
    return map;
  }
};

constexpr double kTolerance = kMarchStep + 1e-9;

TEST(Laser, RangesAndIntensitiesMatchAnIndependentRayMarch) {
  const Room room;
  const LaserSpec spec{.range_max = 4.0, .fov = 1.5 * kPi, .samples = 271};
  const Pose2 sensor{0.1, 0.0, 0.4};
  NoiseDraws noise(1, 1, 0);
  const LaserScan scan = scan_laser(room.scene, spec, sensor, room.robot, noise);

  ASSERT_EQ(scan.ranges.size(), 271u);
  ASSERT_EQ(scan.intensities.size(), 271u);
  EXPECT_DOUBLE_EQ(scan.min_angle, -0.75 * kPi);
  EXPECT_DOUBLE_EQ(scan.max_angle, 0.75 * kPi);
  EXPECT_EQ(scan.range_max, 4.0);

  std::vector<int> hits_per_model(room.scene.models().size(), 0);
  int walls = 0, misses = 0, crossing_the_invisible_box = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double bearing = -0.75 * kPi + 1.5 * kPi * static_cast<double>(i) / 270.0;
    const MarchedHit expected =
        march(room.scene, sensor.translation(), sensor.yaw + bearing, spec.range_max, room.robot, ranger_stops);
    EXPECT_NEAR(scan.ranges[i], expected.range, kTolerance) << "sample " << i;
    EXPECT_EQ(scan.intensities[i], expected.model == room.bright ? 1 : 0) << "sample " << i;
    if (expected.model != kNoModel) ++hits_per_model[static_cast<std::size_t>(expected.model)];
    else if (expected.range < spec.range_max) ++walls;
    else ++misses;
    const MarchedHit unfiltered =
        march(room.scene, sensor.translation(), sensor.yaw + bearing, spec.range_max, room.robot, any_body_stops);
    if (unfiltered.model == room.see_through) ++crossing_the_invisible_box;
  }
  EXPECT_GT(crossing_the_invisible_box, 0);
  // The scan really met what the room was built to show it.
  EXPECT_GT(hits_per_model[static_cast<std::size_t>(room.turned_box)], 0);
  EXPECT_GT(hits_per_model[static_cast<std::size_t>(room.disc_model)], 0);
  EXPECT_GT(hits_per_model[static_cast<std::size_t>(room.bright)], 0);
  EXPECT_EQ(hits_per_model[static_cast<std::size_t>(room.see_through)], 0);
  EXPECT_EQ(hits_per_model[static_cast<std::size_t>(room.robot)], 0);
  EXPECT_GT(walls, 0);
  EXPECT_GT(misses, 0);
}

TEST(Laser, RaysPassThroughTheirOwnRobotButNotAnothers) {
  const Room room;
  const LaserSpec spec{.range_max = 8.0, .fov = 0.0, .samples = 1};
  NoiseDraws noise(1, 1, 0);
  // From inside the robot's own disc, looking along +x at the turned box's
  // side of the room: the own disc does not stop the ray.
  const LaserScan own = scan_laser(room.scene, spec, {0.0, 0.0, 0.0}, room.robot, noise);
  ASSERT_EQ(own.ranges.size(), 1u);
  EXPECT_GT(own.ranges[0], 0.25);
  // The same ray for a sensor of another robot starts inside a body: 0.
  const LaserScan other = scan_laser(room.scene, spec, {0.0, 0.0, 0.0}, room.turned_box, noise);
  EXPECT_EQ(other.ranges[0], 0.0);
}

TEST(Laser, OneSampleLooksStraightAhead) {
  const Room room;
  const LaserSpec spec{.range_max = 8.0, .fov = kPi, .samples = 1};
  NoiseDraws noise(1, 1, 0);
  // Aimed at the disc's centre from (0, 0): it is met at its near edge.
  const Pose2 sensor{0.0, 0.0, std::atan2(2.0, -1.5)};
  const LaserScan scan = scan_laser(room.scene, spec, sensor, room.robot, noise);
  ASSERT_EQ(scan.ranges.size(), 1u);
  EXPECT_EQ(scan.min_angle, 0.0);
  EXPECT_EQ(scan.max_angle, 0.0);
  EXPECT_NEAR(scan.ranges[0], std::hypot(-1.5, 2.0) - 0.2, 1e-9);
}

TEST(Laser, NoSamplesGiveAnEmptyScan) {
  const Room room;
  NoiseDraws noise(1, 1, 0);
  const LaserScan scan = scan_laser(room.scene, {.samples = 0}, {}, room.robot, noise);
  EXPECT_TRUE(scan.ranges.empty());
  EXPECT_TRUE(scan.intensities.empty());
}

// A laser 2 m in front of a long flat wall (the cells from x = 2.0 on),
// in an otherwise empty room: beam i at bearing b reads 2 / cos b exactly.
struct WallAhead {
  Scene scene;
  ModelId robot = kNoModel;
  WallAhead() : scene(make_map()) { robot = add_model(scene, {}, disc(0.4)); }
  static grid::OccupancyGrid make_map() {
    grid::OccupancyGrid map = room();
    add_wall(map, 2.0, -4.0, 2.2, 4.0);
    return map;
  }
  static double range_at(double bearing) { return 2.0 / std::cos(bearing); }
};

constexpr int kNoiseScans = 40;
constexpr int kNoiseSamples = 181;
constexpr double kNoiseFov = kPi / 2.0;

// Range minus the noise-free range, for every beam of kNoiseScans scans.
std::vector<double> range_errors(const LaserSpec& noisy, std::vector<double>* clean_ranges = nullptr) {
  const WallAhead wall;
  std::vector<double> errors;
  for (int step = 0; step < kNoiseScans; ++step) {
    NoiseDraws noise(42, 3, static_cast<std::uint64_t>(step));
    const LaserScan scan = scan_laser(wall.scene, noisy, {}, wall.robot, noise);
    for (int i = 0; i < kNoiseSamples; ++i) {
      const double bearing = -kNoiseFov / 2.0 + kNoiseFov * i / (kNoiseSamples - 1);
      const double clean = WallAhead::range_at(bearing);
      errors.push_back(scan.ranges[static_cast<std::size_t>(i)] - clean);
      if (clean_ranges != nullptr) clean_ranges->push_back(clean);
    }
  }
  return errors;
}

TEST(Laser, NoiseFreeRangesOnAFlatWallAreExact) {
  const LaserSpec spec{.fov = kNoiseFov, .samples = kNoiseSamples};
  for (const double error : range_errors(spec)) EXPECT_NEAR(error, 0.0, 1e-9);
}

TEST(Laser, GaussianNoiseHasTheConfiguredStandardDeviation) {
  const LaserSpec spec{.fov = kNoiseFov, .samples = kNoiseSamples, .noise_sd = 0.05};
  const std::vector<double> errors = range_errors(spec);
  ASSERT_EQ(errors.size(), static_cast<std::size_t>(kNoiseScans * kNoiseSamples));  // 7240
  const auto [mean, sd] = mean_and_sd(errors);
  EXPECT_NEAR(mean, 0.0, 3.0 * 0.05 / std::sqrt(7240.0));
  EXPECT_NEAR(sd, 0.05, 0.05 * 0.04);
}

TEST(Laser, ProportionalNoiseIsBoundedAndUniform) {
  const LaserSpec spec{.fov = kNoiseFov, .samples = kNoiseSamples, .noise_proportional = 0.1};
  std::vector<double> clean;
  const std::vector<double> errors = range_errors(spec, &clean);
  std::vector<double> fractions;
  for (std::size_t i = 0; i < errors.size(); ++i) {
    const double fraction = errors[i] / clean[i];
    EXPECT_LE(std::abs(fraction), 0.1 + 1e-12);
    fractions.push_back(fraction);
  }
  // Uniform on [-0.1, 0.1]: mean 0, sd 0.2 / sqrt(12).
  const auto [mean, sd] = mean_and_sd(fractions);
  EXPECT_NEAR(mean, 0.0, 3.0 * 0.0577 / std::sqrt(7240.0));
  EXPECT_NEAR(sd, 0.2 / std::sqrt(12.0), 0.2 / std::sqrt(12.0) * 0.04);
}

TEST(Laser, AngleJitterMovesEachBeamWithinItsShareOfTheSpacing) {
  const LaserSpec spec{.fov = kNoiseFov, .samples = kNoiseSamples, .angle_jitter = 0.5};
  const WallAhead wall;
  const double spacing = kNoiseFov / (kNoiseSamples - 1);
  std::vector<double> jitters;
  for (int step = 0; step < kNoiseScans; ++step) {
    NoiseDraws noise(42, 3, static_cast<std::uint64_t>(step));
    const LaserScan scan = scan_laser(wall.scene, spec, {}, wall.robot, noise);
    for (int i = 0; i < kNoiseSamples; ++i) {
      const double bearing = -kNoiseFov / 2.0 + spacing * i;
      if (std::abs(bearing) < 5.0 * spacing) continue;  // near 0, cos hides the angle's sign and size
      // The bearing the beam really took, from its range on the wall.
      const double taken = std::copysign(std::acos(2.0 / scan.ranges[static_cast<std::size_t>(i)]), bearing);
      jitters.push_back(taken - bearing);
    }
  }
  for (const double jitter : jitters) EXPECT_LE(std::abs(jitter), 0.25 * spacing + 1e-9);
  // Uniform on ±spacing/4: sd spacing / (2 sqrt 12).
  const auto [mean, sd] = mean_and_sd(jitters);
  EXPECT_NEAR(mean, 0.0, 3.0 * spacing / (2.0 * std::sqrt(12.0)) / std::sqrt(static_cast<double>(jitters.size())));
  EXPECT_NEAR(sd, spacing / (2.0 * std::sqrt(12.0)), spacing / (2.0 * std::sqrt(12.0)) * 0.05);
}

TEST(Laser, ReadingsAtRangeMaxAreNoiseFreeAndNoiseIsClippedToTheRange) {
  const WallAhead wall;
  // Beams within acos(2 / 2.5) of straight ahead meet the wall inside
  // range_max; the others see nothing.
  const LaserSpec spec{.range_max = 2.5, .fov = kPi, .samples = 181, .noise_sd = 0.5, .noise_proportional = 0.3};
  int clipped = 0, noisy = 0;
  for (int step = 0; step < 20; ++step) {
    NoiseDraws noise(5, 3, static_cast<std::uint64_t>(step));
    const LaserScan scan = scan_laser(wall.scene, spec, {}, wall.robot, noise);
    for (int i = 0; i < 181; ++i) {
      const double range = scan.ranges[static_cast<std::size_t>(i)];
      const double clean = WallAhead::range_at(-kPi / 2.0 + kPi * i / 180.0);
      EXPECT_GE(range, 0.0);
      EXPECT_LE(range, 2.5);
      if (!(clean < 2.5) || clean < 0.0) {  // cos <= 0 at the edges: no wall that way either
        EXPECT_EQ(range, 2.5) << "step " << step << " sample " << i;
      } else if (range == 2.5) {
        ++clipped;
      } else if (range != clean) {
        ++noisy;
      }
    }
  }
  EXPECT_GT(clipped, 0);
  EXPECT_GT(noisy, 0);
}

TEST(Laser, TheSameDrawsGiveTheSameScanAndOtherStepsAnother) {
  const WallAhead wall;
  const LaserSpec spec{.fov = kNoiseFov, .samples = 31, .noise_sd = 0.02, .noise_proportional = 0.01,
                       .angle_jitter = 0.3};
  NoiseDraws first(9, 2, 17), again(9, 2, 17), later(9, 2, 18);
  const LaserScan a = scan_laser(wall.scene, spec, {}, wall.robot, first);
  const LaserScan b = scan_laser(wall.scene, spec, {}, wall.robot, again);
  const LaserScan c = scan_laser(wall.scene, spec, {}, wall.robot, later);
  EXPECT_EQ(a.ranges, b.ranges);
  EXPECT_NE(a.ranges, c.ranges);
}

}  // namespace playerkit::sim::laser_test
