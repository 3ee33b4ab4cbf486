#pragma once
// Player 1.5 `power` payloads: constants and packed structs, field for field
// as in wire-format.md §5 (names, order, sizes). Values are in wire units.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <vector>

#include "protocol/fields.hpp"
#include "protocol/fixed_string.hpp"

namespace playerkit::protocol {

inline constexpr std::uint8_t kMainPowerReq = 14;  // power request subtype (uint8); reply carries a power data packet

struct PowerData {
  static constexpr std::string_view kWireName = "player_power_data_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint16_t charge = 0;  // battery voltage in decivolts (0.1 V)

  static constexpr auto fields() {
    return std::tuple{field("charge", &PowerData::charge)};
  }
  friend bool operator==(const PowerData&, const PowerData&) = default;
};

struct PowerConfig {
  static constexpr std::string_view kWireName = "player_power_config_t";
  static constexpr std::size_t kWireSize = 1;

  std::uint8_t subtype = 0;  // PLAYER_MAIN_POWER_REQ (14); reply is a power data packet

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PowerConfig::subtype)};
  }
  friend bool operator==(const PowerConfig&, const PowerConfig&) = default;
};

}  // namespace playerkit::protocol
