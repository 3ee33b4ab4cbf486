#pragma once
// Poses and velocities in SI units, shared by the typed helpers.

#include <array>
#include <cstdint>

namespace playerkit::client {

struct Pose2D {
  double x = 0;    // m
  double y = 0;    // m
  double yaw = 0;  // rad, counter-clockwise
  friend bool operator==(const Pose2D&, const Pose2D&) = default;
};

struct Velocity2D {
  double x = 0;    // m/s, forward
  double y = 0;    // m/s, sideways
  double yaw = 0;  // rad/s
  friend bool operator==(const Velocity2D&, const Velocity2D&) = default;
};

struct Pose3D {
  double x = 0, y = 0, z = 0;           // m
  double roll = 0, pitch = 0, yaw = 0;  // rad
  friend bool operator==(const Pose3D&, const Pose3D&) = default;
};

struct Velocity3D {
  double x = 0, y = 0, z = 0;           // m/s
  double roll = 0, pitch = 0, yaw = 0;  // rad/s
  friend bool operator==(const Velocity3D&, const Velocity3D&) = default;
};

// The geometry replies' pose arrays: x mm, y mm, yaw degrees.
Pose2D planar_pose(const std::array<std::int16_t, 3>& wire);

}  // namespace playerkit::client
