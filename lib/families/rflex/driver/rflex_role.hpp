#pragma once
// Which of the seven rflex views a device is, and its driver's name: the one
// list of the family's drivers (manual §7.34, rflex.md table 1).

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace playerkit::drivers::rflex {

enum class RflexRole : std::uint8_t { position, sonar, ir, bumper, power, aio, dio };

inline constexpr int kRflexRoleCount = 7;

inline constexpr std::array<std::string_view, kRflexRoleCount> kRflexDriverNames{
    "rflex_position", "rflex_sonar", "rflex_ir", "rflex_bumper", "rflex_power", "rflex_aio", "rflex_dio"};

constexpr std::string_view driver_name(RflexRole role) { return kRflexDriverNames[static_cast<std::size_t>(role)]; }

constexpr std::array<RflexRole, kRflexRoleCount> all_rflex_roles() {
  std::array<RflexRole, kRflexRoleCount> roles{};
  for (std::size_t i = 0; i < roles.size(); ++i) roles[i] = static_cast<RflexRole>(i);
  return roles;
}

}  // namespace playerkit::drivers::rflex
