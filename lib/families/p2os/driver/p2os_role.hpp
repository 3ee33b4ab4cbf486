#pragma once
// Which of the eleven p2os views a device is.

#include <cstdint>
#include <string_view>

namespace playerkit::drivers::p2os {

enum class P2osRole : std::uint8_t {
  position,
  sonar,
  gripper,
  power,
  bumper,
  aio,
  dio,
  cmucam,
  compass,
  gyro,
  sound,
};

inline constexpr int kP2osRoleCount = 11;

// "p2os_position", ...
std::string_view driver_name(P2osRole role);

}  // namespace playerkit::drivers::p2os
