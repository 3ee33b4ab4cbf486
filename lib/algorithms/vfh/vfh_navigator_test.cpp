// The vfh driver's behaviour without the driver: goals, turning in place
// (the sheet's cases), arriving, velocity mode against a wall, stalls and
// giving up when boxed in.

#include "algorithms/vfh/vfh_navigator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

namespace playerkit::vfh {
namespace vfh_navigator_test {

constexpr double kPi = std::numbers::pi;
constexpr double kStep = 0.1;

double radians(double degrees) { return degrees * kPi / 180.0; }

// A base on a plane, its 181-reading laser given by `ray`.
struct Robot {
  geometry::Pose2 pose;
  std::function<double(const geometry::Pose2& from, double angle)> ray = [](const geometry::Pose2&, double) {
    return 8.0;
  };
  std::vector<double> ranges;

  Scan scan() {
    ranges.resize(181);
    for (int i = 0; i < 181; ++i) ranges[static_cast<std::size_t>(i)] = std::min(ray(pose, pose.yaw + radians(i - 90)), 8.0);
    return {-kPi / 2, kPi / 180, ranges};
  }
  void move(const Motion& m) {
    pose.yaw = geometry::normalize_angle(pose.yaw + m.turn_rate * kStep);
    pose.x += m.speed * kStep * std::cos(pose.yaw);
    pose.y += m.speed * kStep * std::sin(pose.yaw);
  }
};

TEST(VfhNavigator, TurnsInPlaceTowardsTheGoalsHeadingAsTheSheetSays) {
  Robot robot;
  VfhNavigator navigator{NavigatorSettings{}};
  navigator.go_to({0, 0, radians(90)});
  Motion m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(m.speed, 0.0);
  EXPECT_NEAR(m.turn_rate, radians(20), 1e-9);
  navigator.go_to({0, 0, radians(15)});
  m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_NEAR(m.turn_rate, radians(10), 1e-9);  // the minimum turn rate
}

TEST(VfhNavigator, OnceThereItKeepsTurningToTheHeadingThoughTheTurnCarriesItALittleFurther) {
  Robot robot;
  NavigatorSettings settings;
  settings.distance_epsilon = 0.15;
  VfhNavigator navigator{settings};
  navigator.go_to({0.1, 0.0, radians(120)});  // within reach, facing away from the heading
  Motion m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(m.speed, 0.0);
  EXPECT_GT(m.turn_rate, 0.0);
  // The turn has carried the robot 0.17 m from the point, which is now
  // behind it: it goes on turning left to the heading rather than back
  // right towards the point.
  robot.pose = {-0.07, 0.0, radians(60)};
  m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(m.speed, 0.0);
  EXPECT_GT(m.turn_rate, 0.0);
  // Well away (beyond twice the distance): it drives back to the point first.
  robot.pose = {-0.3, 0.0, radians(60)};
  m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_LT(m.turn_rate, 0.0) << "the point is to its right, behind";
}

TEST(VfhNavigator, AGoalCorrectedByAFewCentimetresDoesNotUndoTheTurnToItsHeading) {
  Robot robot;
  NavigatorSettings settings;
  settings.distance_epsilon = 0.15;
  VfhNavigator navigator{settings};
  navigator.go_to({0.14, 0.0, radians(120)});  // there, facing away from the heading
  Motion m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(navigator.phase(), Phase::aligning);
  EXPECT_GT(m.turn_rate, 0.0);
  // A global planner's localization moves the goal 2 cm and a degree: now
  // just beyond distance_epsilon, ahead. Started over, the robot would
  // drive to the point again; corrected, it goes on turning to the heading.
  navigator.go_to({0.16, 0.0, radians(121)});
  m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(navigator.phase(), Phase::aligning);
  EXPECT_EQ(m.speed, 0.0);
  EXPECT_GT(m.turn_rate, 0.0);
  // A goal further off is a new goal.
  navigator.go_to({2.0, 0.0, 0.0});
  m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(navigator.phase(), Phase::steering);
}

TEST(VfhNavigator, ReachesAGoalInAnAlcoveItsHistogramCallsBlocked) {
  // Walls 1.1 m ahead, 0.8 m right and 0.9 m left, the goal 0.3 m ahead
  // and a little left: hospital_section's goal (1.98, 1.08), which 1.5's
  // VFH (and this one until 2026-12-08) turned in front of for ever.
  Robot robot;
  robot.ray = [](const geometry::Pose2& from, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    double free = 8.0;
    if (c > 1e-9) free = std::min(free, (1.1 - from.x) / c);
    if (s > 1e-9) free = std::min(free, (0.9 - from.y) / s);
    if (s < -1e-9) free = std::min(free, (-0.8 - from.y) / s);
    return free;
  };
  NavigatorSettings settings;
  settings.distance_epsilon = 0.15;
  settings.angle_epsilon = radians(5);
  VfhNavigator navigator{settings};
  navigator.go_to({0.28, 0.1, radians(-100)});
  Motion m;
  int steps = 0;
  for (; steps < 600 && !m.reached && !m.stuck; ++steps) {
    m = navigator.step(robot.pose, robot.scan(), kStep, false);
    robot.move(m);
  }
  EXPECT_TRUE(m.reached) << "after " << steps << " steps at " << robot.pose.x << ", " << robot.pose.y;
  EXPECT_LT(std::hypot(robot.pose.x - 0.28, robot.pose.y - 0.1), 0.15);
}

TEST(VfhNavigator, TurningFirstAndSteeringHandOverWithHysteresisNotAtOneAngle) {
  Robot robot;  // open space
  VfhNavigator navigator{NavigatorSettings{}};  // turn_first_angle 60 degrees
  navigator.go_to({0.0, 5.0, 0.0});            // straight to the left: 90 degrees off
  const auto at_bearing_off = [&](double degrees_off) {
    robot.pose = {0.0, 0.0, radians(90.0 - degrees_off)};
    return navigator.step(robot.pose, robot.scan(), kStep, false);
  };
  Motion m = at_bearing_off(90);
  EXPECT_EQ(m.speed, 0.0) << "turns on the spot first";
  EXPECT_GT(m.turn_rate, 0.0);
  m = at_bearing_off(50);
  EXPECT_EQ(m.speed, 0.0) << "goes on turning below 60 degrees, down to 30";
  m = at_bearing_off(25);
  EXPECT_GT(m.speed, 0.0) << "the planner steers";
  m = at_bearing_off(70);
  EXPECT_GT(m.speed, 0.0) << "led 70 degrees away by the planner: still steering, no turn on the spot";
  m = at_bearing_off(95);
  EXPECT_EQ(m.speed, 0.0) << "beyond 90 degrees: on the spot again";
}

TEST(VfhNavigator, AGoalAlreadyThereIsReachedOnceAndNotAgain) {
  Robot robot;
  VfhNavigator navigator{NavigatorSettings{}};
  navigator.go_to({0.3, 0.2, radians(5)});
  const Motion m = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_TRUE(m.reached);
  EXPECT_FALSE(navigator.goal_active());
  navigator.go_to({0.3, 0.2, radians(5)});  // the same goal again: not a new one
  EXPECT_FALSE(navigator.goal_active());
  EXPECT_FALSE(navigator.step(robot.pose, robot.scan(), kStep, false).reached);
}

TEST(VfhNavigator, DrivesToAGoalInTheOpenAndStopsThere) {
  Robot robot;
  VfhNavigator navigator{NavigatorSettings{}};
  navigator.go_to({3.0, -2.0, radians(-90)});
  bool reached = false;
  for (int step = 0; step < 900 && !reached; ++step) {
    const Motion m = navigator.step(robot.pose, robot.scan(), kStep, false);
    reached = m.reached;
    robot.move(m);
  }
  ASSERT_TRUE(reached) << robot.pose.x << ", " << robot.pose.y;
  EXPECT_LT(std::hypot(robot.pose.x - 3.0, robot.pose.y + 2.0), 0.5);
  EXPECT_LT(std::abs(geometry::angle_difference(robot.pose.yaw, radians(-90))), radians(10));
  const Motion after = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(after.speed, 0.0);
  EXPECT_EQ(after.turn_rate, 0.0);
}

TEST(VfhNavigator, VelocityModeNeverDrivesIntoAWall) {
  Robot robot;
  robot.ray = [](const geometry::Pose2& from, double angle) {
    return std::cos(angle) > 1e-9 ? (2.0 - from.x) / std::cos(angle) : 8.0;
  };
  const NavigatorSettings settings;
  VfhNavigator navigator{settings};
  navigator.drive(0.5, 0.0);  // straight at the wall, faster than max_speed even
  double last_speed = 1.0;
  bool slowed = false;
  for (int step = 0; step < 300; ++step) {
    const Motion m = navigator.step(robot.pose, robot.scan(), kStep, false);
    slowed = slowed || m.speed < last_speed;
    last_speed = m.speed;
    robot.move(m);
  }
  EXPECT_TRUE(slowed);
  EXPECT_GE(2.0 - robot.pose.x, settings.planner.robot_radius + settings.planner.safety_distance);
  EXPECT_LT(last_speed, 0.01);
  navigator.drive(-0.1, 0.2);  // backing away is the client's call
  const Motion back = navigator.step(robot.pose, robot.scan(), kStep, false);
  EXPECT_EQ(back.speed, -0.1);
  EXPECT_EQ(back.turn_rate, 0.2);
}

TEST(VfhNavigator, BacksOffAfterAStallAndGoesOn) {
  Robot robot;
  NavigatorSettings settings;
  VfhNavigator navigator{settings};
  navigator.go_to({5, 0, 0});
  for (int i = 0; i < 5; ++i) robot.move(navigator.step(robot.pose, robot.scan(), kStep, false));
  const Motion stalled = navigator.step(robot.pose, robot.scan(), kStep, true);
  EXPECT_EQ(stalled.speed, -settings.backoff_speed);
  EXPECT_EQ(navigator.stalls(), 1u);
  int backing = 1;
  while (navigator.step(robot.pose, robot.scan(), kStep, false).speed < 0 && backing < 50) ++backing;
  EXPECT_NEAR(backing * kStep, settings.backoff_time + kStep, 2 * kStep);
  EXPECT_TRUE(navigator.goal_active());
  EXPECT_GT(navigator.step(robot.pose, robot.scan(), kStep, false).speed, 0.0);
}

TEST(VfhNavigator, BoxedInItTurnsOnceAndAHalfRoundThenSaysItIsStuck) {
  Robot robot;
  robot.ray = [](const geometry::Pose2&, double) { return 0.5; };
  VfhNavigator navigator{NavigatorSettings{}};
  navigator.go_to({5, 0, 0});
  int steps = 0;
  Motion m;
  while (!m.stuck && steps < 300) {
    m = navigator.step(robot.pose, robot.scan(), kStep, false);
    EXPECT_EQ(m.speed, 0.0);
    robot.move(m);
    ++steps;
  }
  ASSERT_TRUE(m.stuck);
  // A turn and a half at 40 degrees a second: 13.5 seconds.
  EXPECT_NEAR(steps * kStep, 13.5, 0.3);
  EXPECT_EQ(navigator.stuck_events(), 1u);
  EXPECT_FALSE(navigator.goal_active());
}

}  // namespace vfh_navigator_test
}  // namespace playerkit::vfh
