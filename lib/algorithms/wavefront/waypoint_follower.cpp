#include "algorithms/wavefront/waypoint_follower.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace playerkit::wavefront {

void WaypointFollower::follow(std::vector<Eigen::Vector2d> waypoints, double goal_yaw) {
  waypoints_ = std::move(waypoints);
  goal_yaw_ = goal_yaw;
  // The first waypoint is where the robot stood when the plan was made.
  index_ = waypoints_.size() > 1 ? 1 : 0;
  announced_ = false;
}

void WaypointFollower::clear() { waypoints_.clear(); }

double WaypointFollower::distance_from_leg(const Eigen::Vector2d& point) const {
  const Eigen::Vector2d& to = waypoints_[index_];
  const Eigen::Vector2d& from = waypoints_[index_ > 0 ? index_ - 1 : 0];
  const Eigen::Vector2d leg = to - from;
  const double length_squared = leg.squaredNorm();
  const double along = length_squared > 0 ? std::clamp((point - from).dot(leg) / length_squared, 0.0, 1.0) : 0.0;
  return (point - (from + along * leg)).norm();
}

WaypointFollower::Step WaypointFollower::step(const geometry::Pose2& pose) {
  if (waypoints_.empty()) return {};
  const Eigen::Vector2d here(pose.x, pose.y);
  const std::size_t last = waypoints_.size() - 1;
  if ((here - waypoints_[last]).norm() < settings_.distance_epsilon &&
      std::abs(geometry::angle_difference(goal_yaw_, pose.yaw)) < settings_.angle_epsilon) {
    waypoints_.clear();
    return {.action = Action::reached, .target = {}, .new_target = false};
  }
  while (index_ < last && (here - waypoints_[index_]).norm() < settings_.distance_epsilon) ++index_;
  if (distance_from_leg(here) > settings_.stray_distance) return {.action = Action::replan, .target = {}, .new_target = false};

  const Eigen::Vector2d& waypoint = waypoints_[index_];
  double heading = goal_yaw_;
  if (index_ < last) {
    const Eigen::Vector2d onward = waypoints_[index_ + 1] - waypoint;
    heading = std::atan2(onward.y(), onward.x());
  }
  const bool changed = !announced_ || sent_index_ != index_;
  announced_ = true;
  sent_index_ = index_;
  return {.action = Action::drive, .target = {waypoint.x(), waypoint.y(), heading}, .new_target = changed};
}

}  // namespace playerkit::wavefront
