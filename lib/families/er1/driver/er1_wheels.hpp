#pragma once
// The position interface's velocity command as the ER1's two wheel speeds
// and the motor ports they go to (er1.md §3), and the wheels' counts as the
// robot's motion.

#include <cstdint>

#include "families/er1/protocol/er1_commands.hpp"

namespace playerkit::drivers::er1 {

namespace rcm = hardware::er1;

struct WheelSpeeds {
  double left = 0.0;   // mm/s
  double right = 0.0;  // mm/s
  friend bool operator==(const WheelSpeeds&, const WheelSpeeds&) = default;
};

// 1.5 clamped each wheel to 500 mm/s.
inline constexpr double kFastestWheel = 500.0;

// xspeed mm/s and yawspeed deg/s over an axle in m. A wheel that would go
// faster than kFastestWheel slows both by the same factor, so the robot
// keeps to its arc (1.5 clamped the one wheel, turning a curve into another).
[[nodiscard]] WheelSpeeds wheel_speeds(double xspeed, double yawspeed, double axle);

// Whether going from `from` to `to` reverses either wheel (1.5 stops first).
[[nodiscard]] bool reverses(const WheelSpeeds& from, const WheelSpeeds& to);

// Which port each wheel is on: the left motor is mirrored, so its register
// is the negative of its wheel's speed.
struct Wiring {
  rcm::Motor left;
  rcm::Motor right;
  static Wiring from_motor_dir(int motor_dir);
};

// Wheel travel in metres from two readings of a wheel's 32-bit count (a
// wrap is a small step, not a jump of 2^32).
[[nodiscard]] double wheel_travel(std::int32_t now, std::int32_t before);

}  // namespace playerkit::drivers::er1
