#include "algorithms/wavefront/wavefront_navigator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::wavefront {
namespace wavefront_navigator_test {

using Kind = BaseOrder::Kind;
using Event = NavigationEvent::Kind;
constexpr double kPi = std::numbers::pi;

// A 6 m x 4 m room (origin at its corner) with a wall from the bottom up to
// y = 2.5 m at x = 3 m: a goal beyond it is reached round its top.
grid::OccupancyGrid room_with_wall() {
  grid::OccupancyGrid map(120, 80, 0.05, {0.0, 0.0}, grid::CellState::free);
  for (int row = 0; row < 80; ++row) {
    for (int col = 0; col < 120; ++col) {
      const bool border = row == 0 || col == 0 || row == 79 || col == 119;
      const bool wall = col >= 59 && col <= 61 && row < 50;
      if (border || wall) map.set(col, row, grid::CellState::occupied);
    }
  }
  return map;
}

PlannerParameters robot() {
  PlannerParameters parameters;
  parameters.robot_radius = 0.25;
  parameters.safety_distance = 0.1;
  return parameters;
}

// Odometry started elsewhere: odometric = kOffset ∘ map.
const geometry::Pose2 kOffset{10.0, -5.0, kPi / 2};
geometry::Pose2 odometry_at(const geometry::Pose2& map_pose) { return kOffset.compose(map_pose); }

TEST(WavefrontNavigator, PlansRoundTheWallAndHandsTheFirstWaypointDownInTheOdometricFrame) {
  const grid::OccupancyGrid map = room_with_wall();
  WavefrontNavigator navigator(map, robot(), {});
  const geometry::Pose2 start{1.0, 1.0, 0.0};
  ASSERT_TRUE(navigator.set_goal({5.0, 1.0, 0.0}));
  const BaseOrder order = navigator.cycle(odometry_at(start), start, false);
  ASSERT_EQ(order.kind, Kind::drive_to);
  EXPECT_TRUE(navigator.driving());
  const auto& waypoints = navigator.follower().waypoints();
  ASSERT_GE(waypoints.size(), 3u) << "straight through the wall";
  // Every waypoint keeps the robot's clearance (0.35 m) from the wall, which
  // spans x 2.95-3.10 m up to y 2.5 m.
  for (const auto& point : waypoints) {
    const Eigen::Vector2d nearest(std::clamp(point.x(), 2.95, 3.10), std::clamp(point.y(), 0.0, 2.5));
    EXPECT_GE((point - nearest).norm(), 0.35 - 1e-9) << point.transpose();
  }
  // The target, taken back to the map frame, is the follower's waypoint.
  const geometry::Pose2 on_map = kOffset.inverse().compose(order.target);
  const auto& current = waypoints[navigator.follower().current_index()];
  EXPECT_NEAR(on_map.x, current.x(), 1e-9);
  EXPECT_NEAR(on_map.y, current.y(), 1e-9);
  // The same waypoint is not sent again.
  EXPECT_EQ(navigator.cycle(odometry_at(start), start, false).kind, Kind::none);
  EXPECT_EQ(navigator.plans(), 1u);
}

TEST(WavefrontNavigator, AWaypointIsHandedDownAgainWhenTheLocalizationMovesIt) {
  const grid::OccupancyGrid map = room_with_wall();
  WavefrontNavigator navigator(map, robot(), {});
  navigator.set_goal({2.5, 1.0, 0.0});  // in sight: one leg
  const geometry::Pose2 odometry{0.0, 0.0, 0.0};
  ASSERT_EQ(navigator.cycle(odometry, {1.0, 1.0, 0.0}, false).kind, Kind::drive_to);
  // A correction of 3 cm: the waypoint is where it was, near enough.
  EXPECT_EQ(navigator.cycle(odometry, {1.03, 1.0, 0.0}, false).kind, Kind::none);
  // 10 cm: in the odometric frame the goal is now 10 cm nearer.
  const BaseOrder again = navigator.cycle(odometry, {1.1, 1.0, 0.0}, false);
  ASSERT_EQ(again.kind, Kind::drive_to);
  EXPECT_NEAR(again.target.x, 1.4, 1e-9);
  EXPECT_NEAR(again.target.y, 0.0, 1e-9);
  // A heading correction of 5 degrees turns it.
  EXPECT_EQ(navigator.cycle(odometry, {1.1, 1.0, 5.0 * kPi / 180.0}, false).kind, Kind::drive_to);
}

TEST(WavefrontNavigator, TheSameGoalAgainIsNotANewGoal) {
  const grid::OccupancyGrid map = room_with_wall();
  WavefrontNavigator navigator(map, robot(), {});
  EXPECT_TRUE(navigator.set_goal({5.0, 1.0, 0.0}));
  EXPECT_FALSE(navigator.set_goal({5.0005, 1.0, 0.0005}));
  EXPECT_TRUE(navigator.set_goal({5.0, 1.1, 0.0}));
}

TEST(WavefrontNavigator, AGoalInsideTheWallIsRefusedAtOnceAndNothingDrives) {
  const grid::OccupancyGrid map = room_with_wall();
  WavefrontNavigator navigator(map, robot(), {});
  const geometry::Pose2 start{1.0, 1.0, 0.0};
  navigator.set_goal({3.0, 1.0, 0.0});
  EXPECT_EQ(navigator.cycle(odometry_at(start), start, false).kind, Kind::none);
  EXPECT_FALSE(navigator.driving());
  const auto events = navigator.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, Event::refused);
  EXPECT_EQ(events[0].message.rfind("goal (3.00, 1.00) refused: ", 0), 0u) << events[0].message;
  EXPECT_EQ(navigator.goals_refused(), 1u);
}

TEST(WavefrontNavigator, AGoalRefusedWhileDrivingStopsTheRobot) {
  const grid::OccupancyGrid map = room_with_wall();
  WavefrontNavigator navigator(map, robot(), {});
  const geometry::Pose2 start{1.0, 1.0, 0.0};
  navigator.set_goal({5.0, 1.0, 0.0});
  ASSERT_EQ(navigator.cycle(odometry_at(start), start, false).kind, Kind::drive_to);
  navigator.set_goal({3.0, 1.0, 0.0});
  EXPECT_EQ(navigator.cycle(odometry_at(start), start, false).kind, Kind::stop);
  EXPECT_FALSE(navigator.driving());
}

TEST(WavefrontNavigator, AJumpOrAStuckLocalPlannerIsPlannedAgainThenGivenUp) {
  const grid::OccupancyGrid map = room_with_wall();
  NavigatorSettings settings;
  settings.most_plans_per_goal = 3;
  WavefrontNavigator navigator(map, robot(), settings);
  geometry::Pose2 pose{1.0, 1.0, 0.0};
  navigator.set_goal({5.0, 1.0, 0.0});
  ASSERT_EQ(navigator.cycle(odometry_at(pose), pose, false).kind, Kind::drive_to);
  (void)navigator.take_events();
  // The localization jumps 0.6 m (within the path's 1 m stray distance).
  pose = {1.0, 1.6, 0.0};
  (void)navigator.cycle(odometry_at(pose), pose, false);
  auto events = navigator.take_events();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].kind, Event::replanning);
  EXPECT_EQ(events[0].message, "the localization jumped; planning again");
  // The local planner reports a stall: the third plan, the last allowed.
  (void)navigator.cycle(odometry_at(pose), pose, true);
  events = navigator.take_events();
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events[0].message, "the local planner is stuck; planning again");
  EXPECT_EQ(navigator.plans(), 3u);
  // Stuck again: given up, and the robot told to stop.
  EXPECT_EQ(navigator.cycle(odometry_at(pose), pose, true).kind, Kind::stop);
  events = navigator.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, Event::given_up);
  EXPECT_FALSE(navigator.driving());
  EXPECT_EQ(navigator.replans(), 2u);
}

TEST(WavefrontNavigator, ArrivingStopsTheRobotOnceAndSaysSo) {
  const grid::OccupancyGrid map = room_with_wall();
  WavefrontNavigator navigator(map, robot(), {});
  const geometry::Pose2 start{1.0, 1.0, 0.0};
  navigator.set_goal({2.0, 1.0, 0.0});  // in sight: one leg
  ASSERT_EQ(navigator.cycle(odometry_at(start), start, false).kind, Kind::drive_to);
  (void)navigator.take_events();
  const geometry::Pose2 on_the_way{1.4, 1.0, 0.0};
  EXPECT_EQ(navigator.cycle(odometry_at(on_the_way), on_the_way, false).kind, Kind::none);
  const geometry::Pose2 there{1.7, 1.0, 0.05};  // within distance_epsilon and angle_epsilon
  EXPECT_EQ(navigator.cycle(odometry_at(there), there, false).kind, Kind::stop);
  const auto events = navigator.take_events();
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, Event::reached);
  EXPECT_EQ(navigator.goals_reached(), 1u);
  EXPECT_EQ(navigator.cycle(odometry_at(there), there, false).kind, Kind::none);
}

}  // namespace wavefront_navigator_test
}  // namespace playerkit::wavefront
