#include "families/flockofbirds/driver/position3d_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::drivers::flockofbirds {

namespace {

constexpr std::int32_t kArcSecondsPerTurn = 360 * 3600;

std::int32_t millimetres(double mm) {
  if (!std::isfinite(mm)) return 0;
  return static_cast<std::int32_t>(std::clamp(std::round(mm), -2147483648.0, 2147483647.0));
}

}  // namespace

std::int32_t arc_seconds_0_to_360(double degrees) {
  if (!std::isfinite(degrees)) return 0;
  const auto seconds = static_cast<std::int64_t>(std::llround(std::fmod(degrees, 360.0) * 3600.0));
  // Rounding may land on a full turn either way: 359.99999 deg is 0.
  return static_cast<std::int32_t>(((seconds % kArcSecondsPerTurn) + kArcSecondsPerTurn) % kArcSecondsPerTurn);
}

protocol::Position3dData position3d_from_bird(const hardware::flockofbirds::BirdPose& pose) {
  protocol::Position3dData data;
  data.xpos = millimetres(pose.x_mm);
  data.ypos = millimetres(pose.y_mm);
  data.zpos = millimetres(-pose.z_mm);
  data.yaw = arc_seconds_0_to_360(pose.azimuth_deg);
  data.pitch = arc_seconds_0_to_360(pose.elevation_deg);
  data.roll = arc_seconds_0_to_360(pose.roll_deg);
  return data;
}

}  // namespace playerkit::drivers::flockofbirds
