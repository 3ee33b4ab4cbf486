#include "emulators/mobile_base/differential_drive.hpp"

#include "emulators/mobile_base/obstacle_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace playerkit::emulators::mobile_base {

geometry::Pose2 drive_arc(const geometry::Pose2& pose, double distance, double rotation) {
  geometry::Pose2 next = pose;
  if (std::abs(rotation) < 1e-12) {
    next.x += distance * std::cos(pose.yaw);
    next.y += distance * std::sin(pose.yaw);
  } else {
    const double radius = distance / rotation;
    next.x += radius * (std::sin(pose.yaw + rotation) - std::sin(pose.yaw));
    next.y -= radius * (std::cos(pose.yaw + rotation) - std::cos(pose.yaw));
  }
  next.yaw = geometry::normalize_angle(pose.yaw + rotation);
  return next;
}

DifferentialDrive::DifferentialDrive(DriveGeometry geometry, const OdometryError& error,
                                     const grid::OccupancyGrid* map,
                                     const geometry::Pose2& start)
    : geometry_(geometry), error_(error), map_(map), true_pose_(start), random_(error.seed) {}

void DifferentialDrive::command(double speed, double turn_rate) {
  if (!std::isfinite(speed)) speed = 0.0;
  if (!std::isfinite(turn_rate)) turn_rate = 0.0;
  speed_ = std::clamp(speed, -geometry_.max_speed, geometry_.max_speed);
  turn_rate_ = std::clamp(turn_rate, -geometry_.max_turn_rate, geometry_.max_turn_rate);
}

void DifferentialDrive::command_wheels(WheelVelocities wheels) {
  command((wheels.left + wheels.right) / 2.0, (wheels.right - wheels.left) / geometry_.wheelbase);
}

WheelVelocities DifferentialDrive::wheels() const {
  const double speed = last_step_blocked_ ? 0.0 : speed_;
  const double half_difference = turn_rate_ * geometry_.wheelbase / 2.0;
  return {speed - half_difference, speed + half_difference};
}

Contact DifferentialDrive::take_contact() {
  const Contact contact = contact_;
  contact_ = {};
  return contact;
}

void DifferentialDrive::run(double seconds, double max_step) {
  if (!(seconds > 0.0)) return;
  if (!commanded_to_move()) {
    last_step_blocked_ = false;
    return;
  }
  const double steps = std::ceil(seconds / max_step);
  const int count = static_cast<int>(std::clamp(steps, 1.0, 1.0e7));
  const double dt = seconds / count;
  for (int i = 0; i < count; ++i) step(dt);
}

bool DifferentialDrive::blocked(const geometry::Pose2& from, const geometry::Pose2& to,
                                double* bearing) const {
  if (map_ == nullptr || (from.x == to.x && from.y == to.y)) return false;
  const double radius = geometry_.footprint_radius;
  const auto ahead = nearest_obstacle(*map_, to.translation(), radius);
  if (!ahead) return false;
  // Moving away from an obstacle the robot already overlaps is allowed, so
  // a robot placed too close can always back out.
  const auto here = nearest_obstacle(*map_, from.translation(), radius);
  if (here && ahead->distance >= here->distance) return false;
  const Eigen::Vector2d towards = ahead->point - from.translation();
  *bearing = geometry::normalize_angle(std::atan2(towards.y(), towards.x()) - from.yaw);
  return true;
}

void DifferentialDrive::step(double dt) {
  const double distance = speed_ * dt;
  const double rotation = turn_rate_ * dt;
  geometry::Pose2 next = drive_arc(true_pose_, distance, rotation);
  double bearing = 0.0;
  last_step_blocked_ = blocked(true_pose_, next, &bearing);
  double travelled = distance;
  if (last_step_blocked_) {
    next = true_pose_;
    next.yaw = geometry::normalize_angle(true_pose_.yaw + rotation);
    travelled = 0.0;
    contact_ = {true, bearing};
  }
  true_pose_ = next;

  // The encoders see what the wheels did, through the error model.
  const double length = std::abs(travelled);
  double measured_distance = travelled * (1.0 + error_.translation_scale);
  double measured_rotation = rotation * (1.0 + error_.rotation_scale) +
                             error_.heading_drift_per_metre * length;
  if (length > 0.0 && (error_.translation_noise > 0.0 || error_.rotation_noise > 0.0)) {
    std::normal_distribution<double> unit(0.0, 1.0);
    measured_distance += error_.translation_noise * std::sqrt(length) * unit(random_);
    measured_rotation += error_.rotation_noise * std::sqrt(length) * unit(random_);
  }
  odometry_ = drive_arc(odometry_, measured_distance, measured_rotation);
}

}  // namespace playerkit::emulators::mobile_base
