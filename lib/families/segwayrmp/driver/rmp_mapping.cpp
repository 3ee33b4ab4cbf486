#include "families/segwayrmp/driver/rmp_mapping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::drivers::segwayrmp {

namespace rmp = hardware::segwayrmp;

namespace {


double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

std::int32_t whole(double value) {
  return static_cast<std::int32_t>(std::clamp(value, -2147483648.0, 2147483647.0));
}

std::int32_t rounded(double value) { return whole(std::rint(value)); }

// Mean wheel speed, mm/s.
double forward_speed(const rmp::Status& status) {
  return (status.left_wheel_velocity + status.right_wheel_velocity) / rmp::kWheelCountsPerMetrePerSecond * 1000.0 /
         2.0;
}

// An attitude angle in [0, 360) degrees, as 1.5 normalised it.
double attitude_degrees(std::int16_t counts) {
  const double value = std::fmod(counts / rmp::kAngleCountsPerDegree, 360.0);
  return value < 0 ? value + 360.0 : value;
}

}  // namespace

protocol::PositionData position_data(const rmp::Status& status, const rmp::OdometryPose& pose) {
  protocol::PositionData data;
  data.xpos = whole(pose.x * 1000.0);
  data.ypos = whole(pose.y * 1000.0);
  data.yaw = whole(degrees(pose.theta));
  data.xspeed = rounded(forward_speed(status));
  data.yspeed = 0;
  // The RMP counts clockwise turns positive; Player counter-clockwise.
  data.yawspeed = -rounded(status.yaw_rate / rmp::kAngleCountsPerDegree);
  data.stall = 0;
  return data;
}

protocol::Position3dData position3d_data(const rmp::Status& status, const rmp::OdometryPose& pose) {
  protocol::Position3dData data;
  data.xpos = whole(pose.x * 1000.0);
  data.ypos = whole(pose.y * 1000.0);
  data.zpos = 0;
  data.roll = rounded(attitude_degrees(status.roll) * kArcSecondsPerDegree);
  data.pitch = rounded(attitude_degrees(status.pitch) * kArcSecondsPerDegree);
  data.yaw = whole(degrees(pose.theta) * kArcSecondsPerDegree);
  data.xspeed = rounded(forward_speed(status));
  data.rollspeed = rounded(status.roll_rate / rmp::kAngleCountsPerDegree * kArcSecondsPerDegree);
  data.pitchspeed = rounded(status.pitch_rate / rmp::kAngleCountsPerDegree * kArcSecondsPerDegree);
  data.yawspeed = -rounded(status.yaw_rate / rmp::kAngleCountsPerDegree * kArcSecondsPerDegree);
  data.stall = 0;
  return data;
}

protocol::PowerData power_data(const rmp::Status& status) {
  // 1.5's guess, kept: the value is a percentage of a 72 V pack.
  return {.charge = static_cast<std::uint16_t>(std::clamp(std::rint(status.battery * 7.2), 0.0, 65535.0))};
}

}  // namespace playerkit::drivers::segwayrmp
