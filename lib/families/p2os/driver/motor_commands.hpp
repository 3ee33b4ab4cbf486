#pragma once
// A position command (xspeed mm/s, yawspeed deg/s) as the robot's motor
// packets (p2os.md §3.1), for the two velocity modes of VELOCITY_MODE:
//
//  * direct wheel (mode 0, the default): one VEL2 with both wheel speeds;
//  * separate (any other value): VEL (translation) and RVEL (rotation).
//
// The clamps are the `max_xspeed`, `max_yawspeed` and `use_vel_band`
// options. Two deliberate fixes of 1.5: a wheel over max_xspeed scales both
// wheels (1.5 clamped it alone, which bends the path, quirk 7), and a wheel
// speed is rounded to the nearest VEL2 unit rather than truncated.

#include <vector>

#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/robot_params.hpp"

namespace playerkit::drivers::p2os {

struct MotorLimits {
  int max_xspeed = 500;    // mm/s: each wheel (direct), VEL (separate)
  int max_yawspeed = 100;  // deg/s: RVEL (separate)
  bool use_vel_band = false;  // direct: never drive the wheels in opposite directions

  friend bool operator==(const MotorLimits&, const MotorLimits&) = default;
};

enum class VelocityMode { direct_wheel, separate };

struct VelocityCommand {
  int xspeed = 0;    // mm/s
  int yawspeed = 0;  // deg/s, counter-clockwise

  friend bool operator==(const VelocityCommand&, const VelocityCommand&) = default;
};

struct WheelSpeeds {
  double left = 0.0;   // mm/s
  double right = 0.0;  // mm/s
};

// The wheel speeds for `command` after the clamps, before VEL2's units.
WheelSpeeds wheel_speeds(VelocityCommand command, const hardware::p2os::RobotParams& params,
                         const MotorLimits& limits);

// VEL2 with both wheels in the row's Vel2Divisor units.
hardware::p2os::Command vel2_command(VelocityCommand command, const hardware::p2os::RobotParams& params,
                                     const MotorLimits& limits);

// The packets that put `command` into effect in `mode`: one VEL2, or VEL
// then RVEL (1.5 alternated them over three cycles, quirk 8; both go every
// time here).
std::vector<hardware::p2os::Command> motor_commands(VelocityCommand command, VelocityMode mode,
                                                    const hardware::p2os::RobotParams& params,
                                                    const MotorLimits& limits);

}  // namespace playerkit::drivers::p2os
