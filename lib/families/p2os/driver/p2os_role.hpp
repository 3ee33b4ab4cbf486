#pragma once
// Which of the eleven p2os views a device is, and its driver's name: the one
// list of the family's drivers (the specs, the options read on any robot
// section and the built-in list all come from it).

#include <array>
#include <cstddef>
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

// The drivers' names, in the order of P2osRole (manual §7.30).
inline constexpr std::array<std::string_view, kP2osRoleCount> kP2osDriverNames{
    "p2os_position", "p2os_sonar",  "p2os_gripper", "p2os_power", "p2os_bumper", "p2os_aio",
    "p2os_dio",      "p2os_cmucam", "p2os_compass", "p2os_gyro",  "p2os_sound"};

// "p2os_position", ...
constexpr std::string_view driver_name(P2osRole role) {
  return kP2osDriverNames[static_cast<std::size_t>(role)];
}

// Every role, in order.
constexpr std::array<P2osRole, kP2osRoleCount> all_p2os_roles() {
  std::array<P2osRole, kP2osRoleCount> roles{};
  for (std::size_t i = 0; i < roles.size(); ++i) roles[i] = static_cast<P2osRole>(i);
  return roles;
}

}  // namespace playerkit::drivers::p2os
