#include "families/reb/protocol/reb_params.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace playerkit::hardware::reb {

namespace {

constexpr std::array<std::array<double, 3>, 8> kUbotIrPoses = {{
    {35, 0, 0}, {25, 25, 45}, {0, 35, 90}, {-25, 25, 135},
    {-35, 0, 180}, {-25, -25, 225}, {0, -35, 270}, {25, -25, 315},
}};

const RebParams kSlow{.subclass = "slow",
                      .pulses_per_mm = 24.333022,
                      .axle_length_mm = 139.0,
                      .robot_radius_mm = 90.0,
                      .max_wheel_speed_mm_s = 700.0,
                      .max_turn_rate_deg_s = 150.0,
                      .position_kp = 100,
                      .ir_poses = kUbotIrPoses};
const RebParams kFast{.subclass = "fast",
                      .pulses_per_mm = 7.9223794,
                      .axle_length_mm = 139.0,
                      .robot_radius_mm = 90.0,
                      .max_wheel_speed_mm_s = 700.0,
                      .max_turn_rate_deg_s = 150.0,
                      .position_kp = 1200,
                      .ir_poses = kUbotIrPoses};

std::int32_t rounded(double value) {
  constexpr double kMost = std::numeric_limits<std::int32_t>::max();
  if (!(std::abs(value) < kMost)) return value > 0 ? std::numeric_limits<std::int32_t>::max()
                                                   : -std::numeric_limits<std::int32_t>::max();
  return static_cast<std::int32_t>(std::lround(value));
}

}  // namespace

const RebParams& params_for(std::string_view subclass) { return subclass == "fast" ? kFast : kSlow; }

std::int32_t pulses_per_10ms(double mm_per_s, const RebParams& params) {
  return rounded(mm_per_s * params.pulses_per_mm / 100.0);
}

double mm_per_s(double pulses, const RebParams& params) { return pulses * 100.0 / params.pulses_per_mm; }

MotorSpeeds motor_speeds(double speed_mm_s, double turn_rate_deg_s, const RebParams& params) {
  const double half_difference = turn_rate_deg_s * std::numbers::pi / 180.0 * params.axle_length_mm / 2.0;
  double left = speed_mm_s - half_difference;
  double right = speed_mm_s + half_difference;
  const double fastest = std::max(std::abs(left), std::abs(right));
  if (fastest > params.max_wheel_speed_mm_s) {
    const double scale = params.max_wheel_speed_mm_s / fastest;
    left *= scale;
    right *= scale;
  }
  return {.left = pulses_per_10ms(left, params), .right = -pulses_per_10ms(right, params)};
}

BodyVelocity heading_control(double speed_mm_s, double turn_rate_deg_s, double heading_error_deg) {
  double error = std::remainder(heading_error_deg, 360.0);  // [-180, 180]
  const double share = error / 180.0;
  double speed = (1.0 - std::abs(share)) * speed_mm_s;
  double turn = 3.0 * share * turn_rate_deg_s;
  const double speed_limit = std::abs(speed_mm_s);
  const double turn_limit = std::abs(turn_rate_deg_s);
  speed = std::clamp(speed, -speed_limit, speed_limit);
  turn = std::clamp(turn, -turn_limit, turn_limit);
  return {speed, turn};
}

std::uint16_t battery_decivolts(std::int32_t reading) {
  const double decivolts = std::round(reading * 20.0 / 100.0);
  return static_cast<std::uint16_t>(std::clamp(decivolts, 0.0, 65535.0));
}

std::int32_t battery_reading(double volts) { return rounded(volts * 1000.0 / 20.0); }

std::int32_t move_pulses(double mm, const RebParams& params) { return rounded(mm * params.pulses_per_mm); }

std::int32_t turn_pulses(double degrees, const RebParams& params) {
  // Each wheel rolls half the axle times the angle, the left one backwards
  // for a turn to the left.
  const double radians = degrees * std::numbers::pi / 180.0;
  return -rounded(radians * params.axle_length_mm / 2.0 * params.pulses_per_mm);
}

}  // namespace playerkit::hardware::reb
