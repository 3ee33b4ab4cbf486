#include "families/trogdor/protocol/trogdor_units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::hardware::trogdor {

double metres_per_tick() { return std::numbers::pi * kWheelDiameter / kTicksPerWheelTurn; }

double metres_per_second_per_unit() { return metres_per_tick() / kPidPeriod; }

double ticks_per_second_per_unit() { return 1.0 / kPidPeriod; }

std::int32_t wheel_units(double metres_per_second) {
  const double clamped = std::clamp(metres_per_second, -kMaxWheelSpeed, kMaxWheelSpeed);
  auto units = static_cast<std::int32_t>(std::lround(clamped / metres_per_second_per_unit()));
  if (units != 0 && std::abs(units) < kMinimumWheelUnits) units = units < 0 ? -kMinimumWheelUnits : kMinimumWheelUnits;
  return units;
}

WheelPair wheel_units_for(double forward_mm_per_s, double yaw_deg_per_s) {
  const double rotation = yaw_deg_per_s * std::numbers::pi / 180.0 * kAxleLength / 2.0;
  double right = forward_mm_per_s / 1000.0 + rotation;
  double left = forward_mm_per_s / 1000.0 - rotation;
  const double fastest = std::max(std::abs(left), std::abs(right));
  if (fastest > kMaxWheelSpeed) {
    left *= kMaxWheelSpeed / fastest;
    right *= kMaxWheelSpeed / fastest;
  }
  return {.left = wheel_units(left), .right = wheel_units(right)};
}

BodyVelocity body_velocity(std::int32_t left_units, std::int32_t right_units) {
  const double left = left_units * metres_per_second_per_unit();
  const double right = right_units * metres_per_second_per_unit();
  return {.forward = (left + right) / 2.0, .turn_rate = (right - left) / kAxleLength};
}

}  // namespace playerkit::hardware::trogdor
