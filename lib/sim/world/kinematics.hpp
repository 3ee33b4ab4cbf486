#pragma once
// Internal: how a position model moves in one step, as pure functions of
// its spec and state (stage-worlds.md §2.5).

#include <Eigen/Core>

#include "algorithms/geometry/pose2.hpp"
#include "sim/world/model_spec.hpp"

namespace playerkit::sim {

// The velocity (x, y in the robot frame, yaw rate) a command asks of this
// drive, within the spec's velocity bounds. Differential: vy = 0. Omni: as
// commanded. Car: the command is (speed v, -, steering angle φ), giving
// vx = v cos φ and yaw rate v sin φ / wheelbase.
[[nodiscard]] Eigen::Vector3d drive_velocity(const PositionSpec& spec, const Eigen::Vector3d& command);

// One step towards `target`, each axis changing by at most max_acceleration·dt.
[[nodiscard]] Eigen::Vector3d accelerate(const Eigen::Vector3d& velocity, const Eigen::Vector3d& target,
                                         const Eigen::Vector3d& max_acceleration, double dt);

// The pose change of one step in the robot frame: (vx·dt, vy·dt) along the
// current heading, then the turn ω·dt. Composed onto the pose.
[[nodiscard]] inline geometry::Pose2 step_motion(const Eigen::Vector3d& velocity, double dt) {
  return {velocity.x() * dt, velocity.y() * dt, velocity.z() * dt};
}

// The same motion as odometry sees it, each part scaled by (1 + error).
[[nodiscard]] inline geometry::Pose2 odometry_motion(const geometry::Pose2& motion, const Eigen::Vector3d& error) {
  return {motion.x * (1.0 + error.x()), motion.y * (1.0 + error.y()), motion.yaw * (1.0 + error.z())};
}

// Stage's go-to controller: the command (in the drive's terms) that takes
// `now` towards `goal` (both in the localization frame) at up to 0.4 m/s
// and 1 rad/s without overshooting in one step of dt; zero within 2 cm and
// 1° of the goal. Differential: turn to face the goal, drive, turn to its
// heading. Omni: all at once. Car: drive and steer towards the goal's
// position (a car cannot turn in place, so its final heading is not held).
[[nodiscard]] Eigen::Vector3d go_to_command(const PositionSpec& spec, const geometry::Pose2& now,
                                            const geometry::Pose2& goal, double dt);

}  // namespace playerkit::sim
