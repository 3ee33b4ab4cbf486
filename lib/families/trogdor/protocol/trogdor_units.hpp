#pragma once
// The robot's geometry and units (trogdor.md §3): wheel ticks, velocity
// units of ticks per PID period, and a Player command as wheel units.

#include <cstdint>

#include "families/trogdor/protocol/trogdor_messages.hpp"

namespace playerkit::hardware::trogdor {

inline constexpr double kAxleLength = 0.317;          // m, wheel to wheel
inline constexpr double kWheelDiameter = 0.10795;     // m
inline constexpr double kTicksPerWheelTurn = 11600;
inline constexpr double kPidPeriod = 0.0019375;       // s
inline constexpr double kMaxWheelSpeed = 5.0;         // m/s
// The smallest non-zero velocity the controller turns a wheel at.
inline constexpr std::int32_t kMinimumWheelUnits = 5;
// The accelerations the reference driver sets at start-up (units per PID period²).
inline constexpr WheelPair kStartAccelerations{10, 10};
// The body (GET_GEOM): a square of 450 mm centred on the axle.
inline constexpr double kBodySize = 0.45;  // m

// 2.92358e-5 m a tick.
[[nodiscard]] double metres_per_tick();
// 0.0150895 m/s a velocity unit.
[[nodiscard]] double metres_per_second_per_unit();
// Ticks counted in a second at one velocity unit (516.13).
[[nodiscard]] double ticks_per_second_per_unit();

// A wheel speed in m/s as the nearest velocity unit, within ±5 m/s; 1 to 4
// units, too slow for the controller, are raised to 5.
[[nodiscard]] std::int32_t wheel_units(double metres_per_second);

// Player's command (forward mm/s, yaw deg/s) as wheel units. When a wheel
// would exceed 5 m/s both are scaled down together, so the robot keeps the
// curve it was asked for (the reference clamped the one wheel).
[[nodiscard]] WheelPair wheel_units_for(double forward_mm_per_s, double yaw_deg_per_s);

// The body's speeds from the reported wheel velocities: m/s and rad/s.
struct BodyVelocity {
  double forward = 0;
  double turn_rate = 0;
};
[[nodiscard]] BodyVelocity body_velocity(std::int32_t left_units, std::int32_t right_units);

}  // namespace playerkit::hardware::trogdor
