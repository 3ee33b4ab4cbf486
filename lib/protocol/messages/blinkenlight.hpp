#pragma once
// Player 1.5 `blinkenlight` payloads: constants and packed structs, field for field
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

struct BlinkenlightData {
  static constexpr std::string_view kWireName = "player_blinkenlight_data_t";
  static constexpr std::size_t kWireSize = 3;

  std::uint8_t enable = 0;  // 0 = light disabled, non-zero = enabled
  std::uint16_t period_ms = 0;  // flash period (full on/off cycle), ms

  static constexpr auto fields() {
    return std::tuple{field("enable", &BlinkenlightData::enable),
                      field("period_ms", &BlinkenlightData::period_ms)};
  }
  friend bool operator==(const BlinkenlightData&, const BlinkenlightData&) = default;
};

}  // namespace playerkit::protocol
