// The sheet's worked cases (vfh.md §6, computed with 1.5's own routines),
// then what 1.5 did not do: slowing for what is ahead, stopping short of a
// wall it cannot pass, turning one way out of a dead end.

#include "algorithms/vfh/vfh_planner.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <vector>

namespace playerkit::vfh {
namespace vfh_planner_test {

constexpr double kPi = std::numbers::pi;
constexpr double kStep = 0.1;  // s: odometry at 10 Hz

double degrees(double radians) { return radians * 180.0 / kPi; }

// 181 readings from -90 to +90 degrees, as the sheet's fake laser.
std::vector<double> scan_of(const std::function<double(double bearing_degrees)>& range) {
  std::vector<double> ranges(181);
  for (int i = 0; i < 181; ++i) ranges[static_cast<std::size_t>(i)] = range(i - 90);
  return ranges;
}

Scan as_scan(const std::vector<double>& ranges) { return {-kPi / 2, kPi / 180, ranges}; }

struct FirstStep {
  int speed_mm = 0;      // as 1.5 sent them: mm/s
  int turn_degrees = 0;  // deg/s
  std::vector<double> candidates;
};

FirstStep first_step(const std::vector<double>& ranges, double desired) {
  VfhPlanner planner{VfhParameters{}};
  const Steering s = planner.step(as_scan(ranges), desired, kStep, 1.0);
  return {static_cast<int>(std::lround(s.speed * 1000)), static_cast<int>(std::lround(degrees(s.turn_rate))),
          s.candidates};
}

const auto kOpen = [](double) { return 8.0; };

TEST(VfhPlanner, OpenSpaceGoalAheadRampsUpStraight) {
  VfhPlanner planner{VfhParameters{}};
  const std::vector<double> ranges = scan_of(kOpen);
  for (int cycle = 1; cycle <= 12; ++cycle) {
    const Steering s = planner.step(as_scan(ranges), 90, kStep, 1.0);
    EXPECT_EQ(std::lround(s.speed * 1000), std::min(20 * cycle, 200)) << cycle;
    EXPECT_EQ(s.turn_rate, 0.0);
    if (cycle == 1) {
      EXPECT_EQ(s.candidates, (std::vector<double>{90, 40, 140, 90}));
    }
  }
}

TEST(VfhPlanner, OpenSpaceGoalLeftTurnsLeftByTheCheapestCandidate) {
  const FirstStep s = first_step(scan_of(kOpen), 180);
  EXPECT_EQ(s.speed_mm, 20);
  EXPECT_EQ(s.turn_degrees, 27);
  EXPECT_EQ(s.candidates, (std::vector<double>{90, 40, 140}));
}

TEST(VfhPlanner, OpenSpaceGoalBehindTakesTheFirstOfTwoEqualCandidates) {
  const FirstStep s = first_step(scan_of(kOpen), 270);
  EXPECT_EQ(s.speed_mm, 20);
  EXPECT_EQ(s.turn_degrees, -27);
}

TEST(VfhPlanner, AWallAMetreAheadTurnsItLeft) {
  const auto wall_at = [](double metres) {
    return scan_of([metres](double b) { return std::min(metres / std::cos(b * kPi / 180), 8.0); });
  };
  const FirstStep near = first_step(wall_at(1.0), 90);
  EXPECT_EQ(near.speed_mm, 20);
  EXPECT_EQ(near.turn_degrees, 37);
  EXPECT_EQ(near.candidates, (std::vector<double>{160, 17.5}));
  for (const double farther : {1.5, 2.0}) {
    const FirstStep far = first_step(wall_at(farther), 90);
    EXPECT_EQ(far.speed_mm, 20) << farther;
    EXPECT_EQ(far.turn_degrees, 0) << farther;
  }
}

TEST(VfhPlanner, AnObstacleOnTheRightSendsItLeft) {
  const FirstStep s = first_step(scan_of([](double b) { return b >= -30 && b <= -10 ? 0.8 : 8.0; }), 90);
  EXPECT_EQ(s.speed_mm, 20);
  EXPECT_EQ(s.turn_degrees, 24);
  EXPECT_EQ(s.candidates, (std::vector<double>{137.5, 135, 140, 22.5}));
}

// A robot on a plane with one straight wall, moved by what the planner says.
struct MiniWorld {
  double x = 0, y = 0, yaw = 0;
  std::function<double(double x, double y, double angle)> ray;  // free distance from (x, y) along angle

  std::vector<double> scan() const {
    return scan_of([this](double b) { return std::min(ray(x, y, yaw + b * kPi / 180), 8.0); });
  }
  double desired_towards(double gx, double gy) const {
    const double d = 90 + degrees(std::atan2(gy - y, gx - x) - yaw);
    return std::fmod(std::fmod(d, 360.0) + 360.0, 360.0);
  }
  void move(const Steering& s) {
    yaw += s.turn_rate * kStep;
    x += s.speed * kStep * std::cos(yaw);
    y += s.speed * kStep * std::sin(yaw);
  }
};

TEST(VfhPlanner, DrivesToAGoalInTheOpen) {
  MiniWorld world{.x = 0, .y = 0, .yaw = 0, .ray = [](double, double, double) { return 8.0; }};
  VfhPlanner planner{VfhParameters{}};
  int steps = 0;
  while (std::hypot(3 - world.x, 2 - world.y) > 0.2 && steps < 600) {
    const std::vector<double> ranges = world.scan();
    world.move(planner.step(as_scan(ranges), world.desired_towards(3, 2), kStep, 1.0));
    ++steps;
  }
  EXPECT_LT(steps, 600) << "ended at " << world.x << ", " << world.y;
}

// Free distance from (x, y) along `angle` in a corridor 1 m wide (walls at
// y = +-0.5 m) closed by a wall at x = 2 m.
double dead_end(double x, double y, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  double free = 8.0;
  if (c > 1e-9) free = std::min(free, (2.0 - x) / c);
  if (s > 1e-9) free = std::min(free, (0.5 - y) / s);
  if (s < -1e-9) free = std::min(free, (-0.5 - y) / s);
  return free;
}

TEST(VfhPlanner, SlowsForADeadEndStopsShortOfItAndTurnsBackOut) {
  MiniWorld world{.x = 0, .y = 0, .yaw = 0, .ray = dead_end};
  const VfhParameters parameters;
  VfhPlanner planner{parameters};
  double nearest = 1.0;
  std::vector<double> speeds;  // on the way in, until it first stops
  bool stopped = false;
  bool escaped = false;
  for (int step = 0; step < 600 && !escaped; ++step) {
    const std::vector<double> ranges = world.scan();
    const Steering s = planner.step(as_scan(ranges), world.desired_towards(5, 0), kStep, 1.0);
    if (s.speed == 0 && step > 0) stopped = true;
    if (!stopped) speeds.push_back(s.speed);
    world.move(s);
    nearest = std::min({nearest, 2.0 - world.x, 0.5 - world.y, world.y + 0.5});
    escaped = world.x < -0.5;  // back out of the corridor's mouth
  }
  EXPECT_GE(nearest, parameters.robot_radius) << "touched a wall";
  EXPECT_TRUE(escaped) << "still in the corridor at " << world.x << ", " << world.y;
  ASSERT_TRUE(stopped);
  // Full speed early on, then falling off, step by step, before the stop.
  ASSERT_GT(speeds.size(), 20u);
  EXPECT_GT(*std::max_element(speeds.begin(), speeds.end()), 0.18);
  EXPECT_LT(speeds.back(), 0.15);
  const auto peak = std::max_element(speeds.begin(), speeds.end());
  EXPECT_TRUE(std::is_sorted(peak, speeds.end(), std::greater<>())) << "the speed rose again on the way in";
}

TEST(VfhPlanner, NeverComesNearerThanItsRadiusToAWallItCannotPass) {
  // A wall across the whole way at x = 2 m; the goal is behind it.
  MiniWorld world{.x = 0, .y = 0, .yaw = 0, .ray = [](double x, double, double angle) {
                    return std::cos(angle) > 1e-9 ? (2.0 - x) / std::cos(angle) : 8.0;
                  }};
  const VfhParameters parameters;
  VfhPlanner planner{parameters};
  double nearest = 2.0;
  for (int step = 0; step < 400; ++step) {
    const std::vector<double> ranges = world.scan();
    world.move(planner.step(as_scan(ranges), world.desired_towards(5, 0), kStep, 1.0));
    nearest = std::min(nearest, 2.0 - world.x);
  }
  EXPECT_GE(nearest, parameters.robot_radius + parameters.safety_distance);
}

TEST(VfhPlanner, TurnsOneWayOutOfADeadEndAndKeepsTurningThatWay) {
  // Boxed in at 0.5 m, but the right side a little roomier.
  const std::vector<double> boxed = scan_of([](double b) { return b < 0 ? 0.55 : 0.5; });
  VfhPlanner planner{VfhParameters{}};
  const Steering first = planner.step(as_scan(boxed), 90, kStep, 1.0);
  ASSERT_TRUE(first.blocked);
  EXPECT_EQ(first.speed, 0.0);
  EXPECT_LT(first.turn_rate, 0.0) << "turns towards the roomier right";
  // The left now looks roomier; still blocked, it keeps turning right.
  const std::vector<double> mirrored = scan_of([](double b) { return b < 0 ? 0.5 : 0.55; });
  const Steering second = planner.step(as_scan(mirrored), 90, kStep, 1.0);
  ASSERT_TRUE(second.blocked);
  EXPECT_LT(second.turn_rate, 0.0);
  // Once a way opens, it goes.
  const Steering open = planner.step(as_scan(scan_of(kOpen)), 90, kStep, 1.0);
  EXPECT_FALSE(open.blocked);
  EXPECT_GT(open.speed, 0.0);
}

// Free distance from (x, y) along `angle` in an alcove 1.7 m wide (walls at
// y = -0.8 m and y = +0.9 m) closed by a wall at x = 1.1 m: where the
// hospital world's goal (1.98, 1.08) lies.
double alcove(double x, double y, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  double free = 8.0;
  if (c > 1e-9) free = std::min(free, (1.1 - x) / c);
  if (s > 1e-9) free = std::min(free, (0.9 - y) / s);
  if (s < -1e-9) free = std::min(free, (-0.8 - y) / s);
  return free;
}

TEST(VfhPlanner, DrivesStraightAtANearGoalInAnAlcoveThoughTheHistogramBlocksIt) {
  const MiniWorld world{.x = 0, .y = 0, .yaw = 0, .ray = alcove};
  const std::vector<double> ranges = world.scan();
  VfhPlanner planner{VfhParameters{}};
  // Walls all round within 1.1 m: the histogram blocks every direction.
  ASSERT_TRUE(planner.step(as_scan(ranges), 90, kStep, 1.0).blocked);
  // A goal 0.3 m ahead, with nothing in the robot's way to it, is not.
  planner.reset();
  const Steering near = planner.step(as_scan(ranges), 90, kStep, 1.0, 0.3);
  EXPECT_FALSE(near.blocked);
  ASSERT_TRUE(near.direction.has_value());
  EXPECT_EQ(*near.direction, 90.0);
  EXPECT_GT(near.speed, 0.0);
  // Nor one a little off to the side.
  planner.reset();
  const Steering aside = planner.step(as_scan(ranges), 110, kStep, 1.0, 0.3);
  ASSERT_TRUE(aside.direction.has_value());
  EXPECT_EQ(*aside.direction, 110.0);
  EXPECT_GT(aside.turn_rate, 0.0);
  // A goal whose reaching would put the robot's front into the wall is.
  planner.reset();
  EXPECT_TRUE(planner.step(as_scan(ranges), 90, kStep, 1.0, 0.9).blocked);
}

TEST(VfhPlanner, ANearGoalBehindAnObstacleIsNotDrivenAtStraight) {
  // A post 0.4 m ahead, slightly right of the line to a goal 0.8 m ahead.
  const MiniWorld world{.x = 0, .y = 0, .yaw = 0, .ray = [](double, double, double angle) {
                          return std::abs(angle + 0.1) < 0.12 ? 0.4 : 8.0;
                        }};
  const std::vector<double> ranges = world.scan();
  VfhPlanner planner{VfhParameters{}};
  const Steering s = planner.step(as_scan(ranges), 90, kStep, 1.0, 0.8);
  ASSERT_TRUE(s.direction.has_value());
  EXPECT_NE(*s.direction, 90.0);
}

TEST(VfhPlanner, KeepsToOneOfTwoEqualOpeningsThoughTheGoalWobblesBetweenThem) {
  // A post straight ahead 1 m off: an opening each side, mirror images; the
  // goal right behind the post, its direction wobbling two degrees either
  // way as a laser's noise and the robot's sway would make it.
  const std::vector<double> ranges = scan_of([](double b) { return std::abs(b) <= 12 ? 1.0 : 8.0; });
  VfhPlanner planner{VfhParameters{}};
  std::optional<bool> left;
  for (int cycle = 0; cycle < 40; ++cycle) {
    const Steering s = planner.step(as_scan(ranges), cycle % 2 == 0 ? 88 : 92, kStep, 1.0);
    ASSERT_TRUE(s.direction.has_value());
    ASSERT_NE(*s.direction, 90.0) << "straight into the post";
    if (!left) left = *s.direction > 90;
    EXPECT_EQ(*s.direction > 90, *left) << "switched openings at cycle " << cycle;
  }
}

TEST(VfhPlanner, ASpeedLimitCapsTheRamp) {
  VfhPlanner planner{VfhParameters{}};
  const std::vector<double> ranges = scan_of(kOpen);
  for (int i = 0; i < 20; ++i) (void)planner.step(as_scan(ranges), 90, kStep, 0.05);
  EXPECT_DOUBLE_EQ(planner.speed(), 0.05);
}

TEST(VfhPlanner, RefusesParametersItCannotUse) {
  VfhParameters bad;
  bad.sector_angle = 7;
  EXPECT_THROW(VfhPlanner{bad}, std::invalid_argument);
  bad = {};
  bad.min_turn_rate = 2.0;
  EXPECT_THROW(VfhPlanner{bad}, std::invalid_argument);
}

}  // namespace vfh_planner_test
}  // namespace playerkit::vfh
