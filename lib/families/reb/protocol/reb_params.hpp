#pragma once
// The UBot's two rows of 1.5's parameter table (reb.md §3.1), chosen by the
// option `subclass`, and the conversions between the board's units (encoder
// pulses, pulses per 10 ms, 4 mV IR steps, 20 mV battery steps) and SI.

#include <array>
#include <cstdint>
#include <string_view>


namespace playerkit::hardware::reb {

struct RebParams {
  std::string_view subclass;         // "slow", "fast"
  double pulses_per_mm = 0.0;        // encoder pulses per mm a wheel rolls
  double axle_length_mm = 139.0;     // between the wheels
  double robot_radius_mm = 90.0;
  double max_wheel_speed_mm_s = 700.0;
  double max_turn_rate_deg_s = 150.0;
  std::int32_t position_kp = 100;    // position PID at start-up
  // The eight IR sensors: x, y in mm and heading in degrees (index 0 ahead,
  // counter-clockwise every 45 degrees).
  std::array<std::array<double, 3>, 8> ir_poses{};
};

// "fast" gives the fast row; anything else the slow one, as 1.5.
[[nodiscard]] const RebParams& params_for(std::string_view subclass);

// A wheel speed in mm/s as the board's pulses per 10 ms, rounded.
[[nodiscard]] std::int32_t pulses_per_10ms(double mm_per_s, const RebParams& params);
[[nodiscard]] double mm_per_s(double pulses_per_10ms, const RebParams& params);

// The motors' set-points for a body speed (mm/s) and turn rate (deg/s):
// each wheel clamped to the board's limit with the other scaled alike, so
// the robot follows the commanded curve; the right motor negated.
struct MotorSpeeds {
  std::int32_t left = 0;   // motor 2
  std::int32_t right = 0;  // motor 0, negated: negative drives forward
  friend bool operator==(const MotorSpeeds&, const MotorSpeeds&) = default;
};
[[nodiscard]] MotorSpeeds motor_speeds(double speed_mm_s, double turn_rate_deg_s, const RebParams& params);

// 1.5's heading control (reb.md §3.2): the commanded turn rate is a limit and
// a gain; the robot turns towards `heading_error_deg` (commanded heading
// minus the current, wrapped into [-180, 180]) and slows down while far off.
struct BodyVelocity {
  double speed_mm_s = 0.0;
  double turn_rate_deg_s = 0.0;
};
[[nodiscard]] BodyVelocity heading_control(double speed_mm_s, double turn_rate_deg_s, double heading_error_deg);

// Battery: channel 15 counts 20 mV, Player wants decivolts.
[[nodiscard]] std::uint16_t battery_decivolts(std::int32_t reading);
[[nodiscard]] std::int32_t battery_reading(double volts);
// IR: the board counts 4 mV.
inline constexpr int kIrMillivoltsPerStep = 4;

// Position mode (reb.md §3.2): a relative move of `mm` and a turn on the
// spot of `degrees`, both as the left motor's pulses (the right one
// negated for a move, the same for a turn).
[[nodiscard]] std::int32_t move_pulses(double mm, const RebParams& params);
[[nodiscard]] std::int32_t turn_pulses(double degrees, const RebParams& params);

}  // namespace playerkit::hardware::reb
