#include "families/p2os/driver/motor_commands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;

namespace {

// VEL2 carries each wheel as a signed byte; 1.5 kept clear of ±127.
constexpr int kMaxVel2Units = 126;

std::int8_t vel2_units(double speed, int divisor) {
  const double units = std::clamp(std::round(speed / divisor), -double{kMaxVel2Units},
                                  double{kMaxVel2Units});
  return static_cast<std::int8_t>(units);
}

}  // namespace

WheelSpeeds wheel_speeds(VelocityCommand command, const hw::RobotParams& params,
                         const MotorLimits& limits) {
  // Half the wheel speed difference that turns at yawspeed.
  const double half_difference =
      command.yawspeed * std::numbers::pi / 180.0 / params.diff_conv_factor;
  WheelSpeeds wheels{command.xspeed - half_difference, command.xspeed + half_difference};

  const double fastest = std::max(std::abs(wheels.left), std::abs(wheels.right));
  const double limit = std::max(0, limits.max_xspeed);
  if (fastest > limit) {
    // Both wheels slow down together, so the robot keeps its curve.
    const double scale = fastest > 0.0 ? limit / fastest : 0.0;
    wheels.left *= scale;
    wheels.right *= scale;
  }
  if (limits.use_vel_band && wheels.left * wheels.right < 0.0) {
    const double sum = wheels.left + wheels.right;
    if (sum >= 0.0 && wheels.left < 0.0) wheels.left = 0.0;
    if (sum >= 0.0 && wheels.right < 0.0) wheels.right = 0.0;
    if (sum <= 0.0 && wheels.left > 0.0) wheels.left = 0.0;
    if (sum <= 0.0 && wheels.right > 0.0) wheels.right = 0.0;
  }
  return wheels;
}

hw::Command vel2_command(VelocityCommand command, const hw::RobotParams& params,
                         const MotorLimits& limits) {
  const WheelSpeeds wheels = wheel_speeds(command, params, limits);
  const hw::Vel2Wheels units{vel2_units(wheels.left, params.vel2_divisor),
                             vel2_units(wheels.right, params.vel2_divisor)};
  return hw::Command::with_integer(hw::command::vel2, hw::encode_vel2(units));
}

std::vector<hw::Command> motor_commands(VelocityCommand command, VelocityMode mode,
                                        const hw::RobotParams& params, const MotorLimits& limits) {
  if (mode == VelocityMode::direct_wheel) return {vel2_command(command, params, limits)};
  const int max_x = std::max(0, limits.max_xspeed);
  const int max_yaw = std::max(0, limits.max_yawspeed);
  return {hw::Command::with_integer(hw::command::vel, std::clamp(command.xspeed, -max_x, max_x)),
          hw::Command::with_integer(hw::command::rvel, std::clamp(command.yawspeed, -max_yaw, max_yaw))};
}

}  // namespace playerkit::drivers::p2os
