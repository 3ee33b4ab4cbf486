#pragma once
// The Khepera's units and the Player interface's, both ways (khepera.md §3):
// wheel speeds in encoder pulses per 10 ms, counters in pulses, proximity
// readings 0..1023; the interface's metres, radians and seconds.
//
// Speeds are what the client asked for: 1.5 multiplied mm/s by the pulse
// length where it should have divided, so the robot drove at 1/144 of the
// command over 1/12 (about 0.69x at the defaults); see docs/compatibility.md.

#include <cstdint>

namespace playerkit::hardware::khepera {

struct WheelGeometry {
  double millimetres_per_pulse = 1.0 / 12.0;  // encoder_res: the Khepera I counts 12 pulses a millimetre
  double wheelbase_mm = 57.0;                 // between the wheels' contact points (1.5: the size's x)
};

// Pulses per 10 ms, the BIOS's unit of speed.
struct WheelSpeeds {
  std::int64_t left = 0;
  std::int64_t right = 0;
  friend bool operator==(const WheelSpeeds&, const WheelSpeeds&) = default;
};

// The BIOS advances its counters this often, by the speed.
inline constexpr double kSpeedPeriodSeconds = 0.01;

// Forward speed (m/s) and turn rate (rad/s, counter-clockwise positive) as
// the two wheels' speeds, each rounded to the nearest pulse per 10 ms; when
// a wheel would exceed `fastest`, both are scaled down together so the robot
// still drives the commanded arc, slower.
[[nodiscard]] WheelSpeeds wheel_speeds(double speed, double turn_rate, const WheelGeometry& geometry,
                                       std::int64_t fastest);

// A wheel speed in pulses per 10 ms as m/s, and back (unrounded).
[[nodiscard]] double wheel_metres_per_second(double pulses_per_period, const WheelGeometry& geometry);
[[nodiscard]] double pulses_per_period(double metres_per_second, const WheelGeometry& geometry);

// What the wheels did: the centre's distance (m) and the turn (rad,
// counter-clockwise positive), from the two counters' steps or speeds.
struct BodyMotion {
  double distance = 0.0;
  double turn = 0.0;
};
[[nodiscard]] BodyMotion body_motion(double left_pulses, double right_pulses, const WheelGeometry& geometry);

// The difference of two readings of a 32-bit counter, across its wrap.
[[nodiscard]] std::int64_t counter_step(std::int64_t now, std::int64_t before);

// The IR calibration of 1.5 (khepera.md §3.3): range = a * reading^b, in mm.
struct IrCalibration {
  double a = 64.158;
  double b = -0.1238;
};
// Millimetres for a reading; 0 (the power law's infinity) reads as 1, the
// farthest the calibration knows.
[[nodiscard]] double ir_range_mm(std::int64_t reading, const IrCalibration& calibration);
// The reading the calibration gives for `range_mm`, within 1..1023.
[[nodiscard]] std::int64_t ir_reading(double range_mm, const IrCalibration& calibration);

}  // namespace playerkit::hardware::khepera
