#include "interfaces/ptz_limits.hpp"

#include <algorithm>

#include "interfaces/wire_units.hpp"

namespace playerkit::interfaces {

namespace {

double clamp_to_range(double value, double one_end, double other_end) {
  return std::clamp(value, std::min(one_end, other_end), std::max(one_end, other_end));
}

}  // namespace

PtzPose ptz_target(const protocol::PtzCommand& command, const PtzLimits& limits) {
  return {clamp_to_range(radians(command.pan), limits.pan_min, limits.pan_max),
          clamp_to_range(radians(command.tilt), limits.tilt_min, limits.tilt_max),
          clamp_to_range(radians(command.zoom), limits.fov_min, limits.fov_max)};
}

protocol::PtzData ptz_data(const PtzPose& pose, double pan_speed, double tilt_speed) {
  protocol::PtzData data;
  data.pan = wire_value<std::int16_t>(degrees(pose.pan));
  data.tilt = wire_value<std::int16_t>(degrees(pose.tilt));
  data.zoom = wire_value<std::int16_t>(degrees(pose.fov));
  data.panspeed = wire_value<std::int16_t>(degrees(pan_speed));
  data.tiltspeed = wire_value<std::int16_t>(degrees(tilt_speed));
  return data;
}

}  // namespace playerkit::interfaces
