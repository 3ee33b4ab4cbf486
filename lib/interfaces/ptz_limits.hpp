#pragma once
// A pan-tilt-zoom head's reach and Player 1.5's units for it, written once
// for the simulator's ptz and the cameras to come (wire-format.md §5 "ptz"):
// pan, tilt and zoom travel as int16 degrees, zoom being the field of view,
// speeds as deg/s. Inside, everything is radians.

#include <cstdint>

#include "protocol/messages/ptz.hpp"

namespace playerkit::interfaces {

// Where a head can point, in radians. A range given backwards (min > max)
// is taken as its two ends in order.
struct PtzLimits {
  double pan_min = 0.0;
  double pan_max = 0.0;
  double tilt_min = 0.0;
  double tilt_max = 0.0;
  double fov_min = 0.0;  // zoomed in: the narrowest field of view
  double fov_max = 0.0;  // zoomed out
};

// A head's pose, or where it is told to go: radians.
struct PtzPose {
  double pan = 0.0;
  double tilt = 0.0;
  double fov = 0.0;
  friend bool operator==(const PtzPose&, const PtzPose&) = default;
};

// The command's absolute pan, tilt and zoom, clamped to the limits.
[[nodiscard]] PtzPose ptz_target(const protocol::PtzCommand& command, const PtzLimits& limits);

// A pose (and speeds, rad/s) as the data struct: whole degrees, rounded.
[[nodiscard]] protocol::PtzData ptz_data(const PtzPose& pose, double pan_speed = 0.0, double tilt_speed = 0.0);

}  // namespace playerkit::interfaces
