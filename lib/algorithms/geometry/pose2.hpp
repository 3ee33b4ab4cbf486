#pragma once
// A rigid 2-D pose (x, y in metres, yaw in radians) and the few operations
// every localization and mapping algorithm here needs. Header-only, Eigen.

#include <Eigen/Core>

#include <cmath>
#include <numbers>

namespace playerkit::geometry {

// Flags and reports speak degrees; everything inside speaks radians.
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

// Wraps an angle into (-pi, pi].
inline double normalize_angle(double angle) {
  // Most angles are in range already (a yaw plus a small turn): std::remainder
  // would give them back unchanged, at the cost of a library call.
  if (angle > -std::numbers::pi && angle <= std::numbers::pi) return angle;
  angle = std::remainder(angle, 2.0 * std::numbers::pi);
  if (angle <= -std::numbers::pi) angle += 2.0 * std::numbers::pi;
  return angle;
}

// Smallest signed rotation that takes `from` to `to`.
inline double angle_difference(double to, double from) { return normalize_angle(to - from); }

struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;

  Eigen::Vector2d translation() const { return {x, y}; }

  // this * other: `other` is expressed in this pose's frame.
  Pose2 compose(const Pose2& other) const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {x + c * other.x - s * other.y, y + s * other.x + c * other.y,
            normalize_angle(yaw + other.yaw)};
  }

  Pose2 inverse() const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {-c * x - s * y, s * x - c * y, normalize_angle(-yaw)};
  }

  // The pose of `other` seen from this pose: inverse() * other.
  Pose2 between(const Pose2& other) const { return inverse().compose(other); }

  // A point given in this pose's frame, in the parent frame.
  Eigen::Vector2d transform(const Eigen::Vector2d& point) const {
    const double c = std::cos(yaw), s = std::sin(yaw);
    return {x + c * point.x() - s * point.y(), y + s * point.x() + c * point.y()};
  }

  friend bool operator==(const Pose2&, const Pose2&) = default;
};

}  // namespace playerkit::geometry
