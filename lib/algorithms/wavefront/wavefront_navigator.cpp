#include "algorithms/wavefront/wavefront_navigator.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

namespace playerkit::wavefront {

namespace {

// A new goal differs from the last by more than these (1.5's test).
constexpr double kSameGoalDistance = 0.001;  // m
constexpr double kSameGoalAngle = 0.001;     // rad
// The waypoint is handed down again when the localization has moved it this
// much in the odometric frame since it was sent: the local planner steers
// by odometry, and would otherwise stop where the old estimate put it.
constexpr double kResendDistance = 0.05;                    // m
constexpr double kResendAngle = 3.0 * std::numbers::pi / 180.0;  // rad

std::string point_text(const geometry::Pose2& pose) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.2f, %.2f)", pose.x, pose.y);
  return text;
}

}  // namespace

WavefrontNavigator::WavefrontNavigator(const grid::OccupancyGrid& map, const PlannerParameters& planner,
                                       const NavigatorSettings& settings)
    : settings_(settings), planner_(map, planner), follower_(settings.follower) {}

bool WavefrontNavigator::set_goal(const geometry::Pose2& goal) {
  if (goal_ && std::hypot(goal.x - goal_->x, goal.y - goal_->y) <= kSameGoalDistance &&
      std::abs(geometry::angle_difference(goal.yaw, goal_->yaw)) <= kSameGoalAngle) {
    return false;
  }
  goal_ = goal;
  pending_goal_ = goal;
  plans_for_goal_ = 0;
  return true;
}

void WavefrontNavigator::reset() {
  goal_.reset();
  pending_goal_.reset();
  last_map_pose_.reset();
  follower_.clear();
  driving_ = false;
}

std::vector<NavigationEvent> WavefrontNavigator::take_events() { return std::exchange(events_, {}); }

void WavefrontNavigator::say(NavigationEvent::Kind kind, std::string message) {
  events_.push_back({kind, std::move(message)});
}

BaseOrder WavefrontNavigator::cycle(const geometry::Pose2& odometry, const geometry::Pose2& map_pose,
                                    bool local_planner_stalled) {
  BaseOrder order;
  // How to hand a map-frame waypoint down to the local planner.
  to_odometry_ = odometry.compose(map_pose.inverse());
  if (pending_goal_) {
    plan(map_pose, *std::exchange(pending_goal_, std::nullopt), order);
  } else if (follower_.active()) {
    const bool jumped = last_map_pose_ && std::hypot(map_pose.x - last_map_pose_->x,
                                                     map_pose.y - last_map_pose_->y) > settings_.jump_distance;
    const bool stuck = local_planner_stalled && driving_;
    if (jumped || stuck) replan(map_pose, jumped ? "the localization jumped" : "the local planner is stuck", order);
  }
  last_map_pose_ = map_pose;
  if (follower_.active()) follow(map_pose, order);
  return order;
}

void WavefrontNavigator::plan(const geometry::Pose2& from, const geometry::Pose2& goal, BaseOrder& order) {
  ++plans_;
  ++plans_for_goal_;
  const PlanResult result = planner_.plan({from.x, from.y}, {goal.x, goal.y});
  if (!result.found()) {
    ++refused_;
    say(NavigationEvent::Kind::refused,
        "goal " + point_text(goal) + " refused: " + describe_failure(result, planner_.parameters()));
    give_up(order);
    return;
  }
  follower_.follow(result.waypoints, goal.yaw);
}

void WavefrontNavigator::replan(const geometry::Pose2& from, const std::string& why, BaseOrder& order) {
  if (plans_for_goal_ >= settings_.most_plans_per_goal) {
    say(NavigationEvent::Kind::given_up,
        why + " again after " + std::to_string(plans_for_goal_) + " plans; goal given up");
    give_up(order);
    return;
  }
  ++replans_;
  say(NavigationEvent::Kind::replanning, why + "; planning again");
  plan(from, *goal_, order);
}

void WavefrontNavigator::follow(const geometry::Pose2& map_pose, BaseOrder& order) {
  const WaypointFollower::Step step = follower_.step(map_pose);
  switch (step.action) {
    case WaypointFollower::Action::idle:
      return;
    case WaypointFollower::Action::reached:
      ++reached_;
      say(NavigationEvent::Kind::reached, "goal " + point_text(*goal_) + " reached");
      give_up(order);
      return;
    case WaypointFollower::Action::replan:
      replan(map_pose, "the robot strayed from the path", order);
      if (follower_.active()) follow(map_pose, order);
      return;
    case WaypointFollower::Action::drive: {
      const geometry::Pose2 target = to_odometry_.compose(step.target);
      const bool moved = std::hypot(target.x - sent_.x, target.y - sent_.y) > kResendDistance ||
                         std::abs(geometry::angle_difference(target.yaw, sent_.yaw)) > kResendAngle;
      if (step.new_target || !driving_ || moved) {
        order = {BaseOrder::Kind::drive_to, target};
        sent_ = target;
        driving_ = true;
      }
      return;
    }
  }
}

// Not driving any more: the robot is told to stop where it is.
void WavefrontNavigator::give_up(BaseOrder& order) {
  follower_.clear();
  if (driving_) order = {BaseOrder::Kind::stop, {}};
  driving_ = false;
}

}  // namespace playerkit::wavefront
