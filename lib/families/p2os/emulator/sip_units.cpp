#include "families/p2os/emulator/sip_units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::emulators::p2os {
namespace {

// x mod m in [0, m) for any finite x; 0 for the rest.
long wrap(double units, long modulus) {
  if (!std::isfinite(units)) return 0;
  const double rounded = std::round(std::fmod(units, static_cast<double>(modulus)));
  long value = static_cast<long>(rounded) % modulus;
  if (value < 0) value += modulus;
  return value;
}

double saturate(double value, double low, double high) {
  return std::isfinite(value) ? std::clamp(value, low, high) : 0.0;
}

}  // namespace

std::uint16_t position_units(double metres, const hardware::p2os::RobotParams& params) {
  return static_cast<std::uint16_t>(
      wrap(metres * 1000.0 / params.dist_conv_factor, kPositionUnitsWrap));
}

std::int16_t heading_units(double radians, const hardware::p2os::RobotParams& params) {
  double turn = std::fmod(radians, 2.0 * std::numbers::pi);
  if (turn < 0.0) turn += 2.0 * std::numbers::pi;
  return static_cast<std::int16_t>(
      wrap(turn / params.angle_conv_factor, params.heading_units_per_turn()));
}

std::int16_t velocity_units(double metres_per_second, const hardware::p2os::RobotParams& params) {
  const double units = std::round(metres_per_second * 1000.0 / params.vel_conv_factor);
  return static_cast<std::int16_t>(saturate(units, -32768.0, 32767.0));
}

std::uint16_t range_units(double metres, const hardware::p2os::RobotParams& params) {
  const double units = std::round(metres * 1000.0 / params.range_conv_factor);
  return static_cast<std::uint16_t>(saturate(units, 0.0, 65535.0));
}

}  // namespace playerkit::emulators::p2os
