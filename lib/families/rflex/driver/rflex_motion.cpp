#include "families/rflex/driver/rflex_motion.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace playerkit::drivers::rflex {

namespace hw = hardware::rflex;

namespace {

constexpr std::uint32_t kTranslationTorque = 30000;
constexpr std::uint32_t kRotationTorque = 35000;
constexpr std::uint32_t kRotationAcceleration = 100000;

// |trunc(value)| as the field holds it, saturated instead of wrapping.
std::uint32_t magnitude(double value) {
  const double whole = std::fabs(std::trunc(value));
  if (!std::isfinite(whole)) return 0;
  return whole >= static_cast<double>(std::numeric_limits<std::uint32_t>::max())
             ? std::numeric_limits<std::uint32_t>::max()
             : static_cast<std::uint32_t>(whole);
}

}  // namespace

std::pair<hw::AxisCommand, hw::AxisCommand> velocity_commands(double xspeed, double yawspeed,
                                                              const RflexSettings& settings) {
  const double turn = yawspeed * std::numbers::pi / 180.0;
  return {hw::AxisCommand{hw::kTranslationAxis,
                          hw::avoid_escape_bytes(magnitude(xspeed * settings.odo_distance_conversion)),
                          magnitude(settings.default_trans_acceleration * settings.odo_distance_conversion),
                          kTranslationTorque, xspeed >= 0},
          hw::AxisCommand{hw::kRotationAxis, hw::avoid_escape_bytes(magnitude(turn * settings.odo_angle_conversion)),
                          kRotationAcceleration, kRotationTorque, yawspeed >= 0}};
}

std::pair<hw::AxisCommand, hw::AxisCommand> rest_commands(const RflexSettings& settings) {
  return {hw::AxisCommand{hw::kTranslationAxis, 0,
                          magnitude(settings.default_trans_acceleration * settings.odo_distance_conversion), 0, false},
          hw::AxisCommand{hw::kRotationAxis, 0,
                          magnitude(settings.default_rot_acceleration * settings.odo_angle_conversion), 0, false}};
}

}  // namespace playerkit::drivers::rflex
