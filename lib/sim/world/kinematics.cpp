#include "sim/world/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::sim {

namespace {

// Stage's go-to controller (stage-worlds.md §2.5).
constexpr double kGoToSpeed = 0.4;            // m/s
constexpr double kGoToTurnRate = 1.0;         // rad/s
constexpr double kGoToTolerance = 0.02;       // m
constexpr double kGoToAngleTolerance = std::numbers::pi / 180.0;
// A differential robot drives only once facing the goal this closely;
// further off it turns in place first.
constexpr double kGoToFacing = 0.1;            // rad
constexpr double kCarSteeringLimit = std::numbers::pi / 4.0;

double clamp_bounds(double value, double low, double high) { return std::min(std::max(value, low), high); }

// A rate that reaches `remaining` in one step but not faster than `limit`.
double capped_rate(double remaining, double dt, double limit) {
  return clamp_bounds(remaining / dt, -limit, limit);
}

}  // namespace

Eigen::Vector3d drive_velocity(const PositionSpec& spec, const Eigen::Vector3d& command) {
  const Eigen::Vector3d& low = spec.min_velocity;
  const Eigen::Vector3d& high = spec.max_velocity;
  switch (spec.drive) {
    case Drive::omnidirectional:
      return command.cwiseMax(low).cwiseMin(high);
    case Drive::car: {
      const double speed = clamp_bounds(command.x(), low.x(), high.x());
      const double steering = command.z();
      const double turn = spec.wheelbase > 0.0 ? speed * std::sin(steering) / spec.wheelbase : 0.0;
      return {speed * std::cos(steering), 0.0, clamp_bounds(turn, low.z(), high.z())};
    }
    case Drive::differential:
      break;
  }
  return {clamp_bounds(command.x(), low.x(), high.x()), 0.0, clamp_bounds(command.z(), low.z(), high.z())};
}

Eigen::Vector3d accelerate(const Eigen::Vector3d& velocity, const Eigen::Vector3d& target,
                           const Eigen::Vector3d& max_acceleration, double dt) {
  Eigen::Vector3d next;
  for (int axis = 0; axis < 3; ++axis) {
    const double most = max_acceleration[axis] * dt;  // infinite: reached at once
    const double change = target[axis] - velocity[axis];
    // Within reach the target itself, not velocity + change, which rounds.
    next[axis] = std::abs(change) <= most ? target[axis] : velocity[axis] + (change > 0.0 ? most : -most);
  }
  return next;
}

Eigen::Vector3d go_to_command(const PositionSpec& spec, const geometry::Pose2& now, const geometry::Pose2& goal,
                              double dt) {
  const geometry::Pose2 ahead = now.between(goal);  // the goal in the robot's frame
  const double distance = std::hypot(ahead.x, ahead.y);
  const double bearing = distance > 0.0 ? std::atan2(ahead.y, ahead.x) : 0.0;
  const bool arrived = distance <= kGoToTolerance;
  const double final_turn = std::abs(ahead.yaw) > kGoToAngleTolerance ? capped_rate(ahead.yaw, dt, kGoToTurnRate) : 0.0;
  const double speed = std::min(kGoToSpeed, distance / dt);

  switch (spec.drive) {
    case Drive::omnidirectional: {
      if (arrived) return {0.0, 0.0, final_turn};
      // Straight at the goal in the robot's frame; the turn runs alongside.
      return {speed * ahead.x / distance, speed * ahead.y / distance, final_turn};
    }
    case Drive::car: {
      if (arrived) return Eigen::Vector3d::Zero();
      return {speed, 0.0, clamp_bounds(bearing, -kCarSteeringLimit, kCarSteeringLimit)};
    }
    case Drive::differential:
      break;
  }
  if (arrived) return {0.0, 0.0, final_turn};
  const double turn = capped_rate(bearing, dt, kGoToTurnRate);
  if (std::abs(bearing) > kGoToFacing) return {0.0, 0.0, turn};
  return {speed, 0.0, turn};
}

}  // namespace playerkit::sim
