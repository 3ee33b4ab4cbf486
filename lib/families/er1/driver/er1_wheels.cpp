#include "families/er1/driver/er1_wheels.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::drivers::er1 {

WheelSpeeds wheel_speeds(double xspeed, double yawspeed, double axle) {
  const double rotation = yawspeed * std::numbers::pi / 180.0 * axle * 1000.0 / 2.0;
  WheelSpeeds wheels{.left = xspeed - rotation, .right = xspeed + rotation};
  const double fastest = std::max(std::abs(wheels.left), std::abs(wheels.right));
  if (fastest > kFastestWheel) {
    wheels.left *= kFastestWheel / fastest;
    wheels.right *= kFastestWheel / fastest;
  }
  return wheels;
}

bool reverses(const WheelSpeeds& from, const WheelSpeeds& to) {
  return from.left * to.left < 0.0 || from.right * to.right < 0.0;
}

Wiring Wiring::from_motor_dir(int motor_dir) {
  if (motor_dir < 0) return {.left = rcm::Motor::port1, .right = rcm::Motor::port0};
  return {.left = rcm::Motor::port0, .right = rcm::Motor::port1};
}

double wheel_travel(std::int32_t now, std::int32_t before) {
  const auto step = static_cast<std::int32_t>(static_cast<std::uint32_t>(now) - static_cast<std::uint32_t>(before));
  return step * rcm::kMillimetresPerTick / 1000.0;
}

}  // namespace playerkit::drivers::er1
