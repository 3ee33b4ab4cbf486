#include "algorithms/wavefront/waypoint_follower.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace playerkit::wavefront {
namespace waypoint_follower_test {

using Action = WaypointFollower::Action;
constexpr double kPi = std::numbers::pi;

std::vector<Eigen::Vector2d> l_shaped() { return {{0, 0}, {2, 0}, {2, 2}}; }

TEST(WaypointFollower, HandsOutEachWaypointFacingTheNextLegThenTheGoalsHeading) {
  WaypointFollower follower;
  follower.follow(l_shaped(), kPi);
  WaypointFollower::Step s = follower.step({0, 0, 0});
  ASSERT_EQ(s.action, Action::drive);
  EXPECT_TRUE(s.new_target);
  EXPECT_DOUBLE_EQ(s.target.x, 2);
  EXPECT_DOUBLE_EQ(s.target.y, 0);
  EXPECT_DOUBLE_EQ(s.target.yaw, kPi / 2);  // along the leg beyond it
  s = follower.step({1, 0.1, 0});
  EXPECT_FALSE(s.new_target);  // the same waypoint: nothing new to send
  s = follower.step({1.7, 0, 0});  // within 0.45 m: passed, whatever the heading
  EXPECT_TRUE(s.new_target);
  EXPECT_DOUBLE_EQ(s.target.y, 2);
  EXPECT_DOUBLE_EQ(s.target.yaw, kPi);
  EXPECT_EQ(follower.step({2, 1.7, kPi / 2}).action, Action::drive);  // at the goal, facing the wrong way
  EXPECT_EQ(follower.step({2, 1.7, kPi - 0.1}).action, Action::reached);
  EXPECT_EQ(follower.step({2, 1.7, kPi - 0.1}).action, Action::idle);
}

TEST(WaypointFollower, AsksForANewPlanWhenTheRobotStrays) {
  WaypointFollower follower;
  follower.follow(l_shaped(), 0);
  EXPECT_EQ(follower.step({1, 0.9, 0}).action, Action::drive);
  EXPECT_EQ(follower.step({1, 1.1, 0}).action, Action::replan);
  EXPECT_EQ(follower.step({1, -1.2, 0}).action, Action::replan);
}

TEST(WaypointFollower, APlanOfOnePointIsTheGoalItself) {
  WaypointFollower follower;
  follower.follow({{0.1, 0.0}}, 0);
  EXPECT_EQ(follower.step({0, 0, 0}).action, Action::reached);
  EXPECT_FALSE(follower.active());
  EXPECT_EQ(follower.step({0, 0, 0}).action, Action::idle);
}

}  // namespace waypoint_follower_test
}  // namespace playerkit::wavefront
