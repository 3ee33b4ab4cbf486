#pragma once
// Player 1.5 `rwi` payloads: constants and packed structs, field for field
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

struct RwiConfig {
  static constexpr std::string_view kWireName = "player_rwi_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t request = 0;  // driver-specific request code
  std::uint8_t value = 0;  // argument

  static constexpr auto fields() {
    return std::tuple{field("request", &RwiConfig::request),
                      field("value", &RwiConfig::value)};
  }
  friend bool operator==(const RwiConfig&, const RwiConfig&) = default;
};

}  // namespace playerkit::protocol
