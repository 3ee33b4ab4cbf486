#include "families/khepera/protocol/khepera_units.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::hardware::khepera {

namespace {

constexpr double kMillimetresPerMetre = 1000.0;
constexpr std::int64_t kBrightest = 1023;

}  // namespace

double wheel_metres_per_second(double pulses, const WheelGeometry& geometry) {
  return pulses * geometry.millimetres_per_pulse / kMillimetresPerMetre / kSpeedPeriodSeconds;
}

double pulses_per_period(double metres_per_second, const WheelGeometry& geometry) {
  return metres_per_second * kMillimetresPerMetre * kSpeedPeriodSeconds / geometry.millimetres_per_pulse;
}

WheelSpeeds wheel_speeds(double speed, double turn_rate, const WheelGeometry& geometry, std::int64_t fastest) {
  const double half_track = geometry.wheelbase_mm / kMillimetresPerMetre / 2.0;
  double left = pulses_per_period(speed - turn_rate * half_track, geometry);
  double right = pulses_per_period(speed + turn_rate * half_track, geometry);
  const double largest = std::max(std::abs(left), std::abs(right));
  if (largest > static_cast<double>(fastest) && largest > 0.0) {
    const double shrink = static_cast<double>(fastest) / largest;
    left *= shrink;
    right *= shrink;
  }
  return {std::llround(left), std::llround(right)};
}

BodyMotion body_motion(double left_pulses, double right_pulses, const WheelGeometry& geometry) {
  const double left = left_pulses * geometry.millimetres_per_pulse;
  const double right = right_pulses * geometry.millimetres_per_pulse;
  return {(left + right) / 2.0 / kMillimetresPerMetre, (right - left) / geometry.wheelbase_mm};
}

std::int64_t counter_step(std::int64_t now, std::int64_t before) {
  const auto difference = static_cast<std::uint32_t>(now) - static_cast<std::uint32_t>(before);
  return static_cast<std::int32_t>(difference);
}

double ir_range_mm(std::int64_t reading, const IrCalibration& calibration) {
  const double value = static_cast<double>(std::clamp<std::int64_t>(reading, 1, kBrightest));
  return calibration.a * std::pow(value, calibration.b);
}

std::int64_t ir_reading(double range_mm, const IrCalibration& calibration) {
  if (!(range_mm > 0.0)) return kBrightest;
  const double value = std::pow(range_mm / calibration.a, 1.0 / calibration.b);
  if (!std::isfinite(value)) return kBrightest;
  return std::clamp<std::int64_t>(std::llround(value), 1, kBrightest);
}

}  // namespace playerkit::hardware::khepera
