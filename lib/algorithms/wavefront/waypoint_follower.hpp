#pragma once
// Handing a plan's waypoints to a local planner one at a time (wavefront.md
// §2.5), as pure logic in the map frame: which waypoint is current, when the
// goal is reached, and when the robot has strayed so far from the path that
// it should be planned again. Unlike 1.5, an intermediate waypoint's heading
// is the direction of the path beyond it (1.5 gave every waypoint the final
// heading, so the robot turned towards it at each one), a waypoint counts as
// passed once the robot is within distance_epsilon of it, whatever its
// heading, and there are no separate rotation waypoints: the local planner
// turns as it drives.

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "algorithms/geometry/pose2.hpp"

namespace playerkit::wavefront {

struct FollowerSettings {
  double distance_epsilon = 0.45;        // m: at a waypoint, or at the goal
  double angle_epsilon = 0.17453292519943295;  // rad (10 degrees): facing the goal's heading
  double stray_distance = 1.0;           // m from the path: plan again
};

class WaypointFollower {
 public:
  explicit WaypointFollower(const FollowerSettings& settings = {}) : settings_(settings) {}

  // A plan's waypoints (the start first, the goal last) and the goal's heading.
  void follow(std::vector<Eigen::Vector2d> waypoints, double goal_yaw);
  void clear();

  enum class Action {
    idle,     // nothing to follow
    drive,    // go to `target`
    reached,  // at the goal: once, then idle
    replan,   // off the path by more than stray_distance
  };
  struct Step {
    Action action = Action::idle;
    geometry::Pose2 target;    // for drive
    bool new_target = false;   // drive: a different waypoint than last step's
  };
  Step step(const geometry::Pose2& pose);

  [[nodiscard]] bool active() const { return !waypoints_.empty(); }
  [[nodiscard]] std::size_t current_index() const { return index_; }
  [[nodiscard]] const std::vector<Eigen::Vector2d>& waypoints() const { return waypoints_; }

 private:
  [[nodiscard]] double distance_from_leg(const Eigen::Vector2d& point) const;

  FollowerSettings settings_;
  std::vector<Eigen::Vector2d> waypoints_;
  double goal_yaw_ = 0;
  std::size_t index_ = 0;        // the waypoint being driven to
  std::size_t sent_index_ = 0;   // the one last handed out (index_ + 1: none yet)
  bool announced_ = false;
};

}  // namespace playerkit::wavefront
