#pragma once
// Player 1.5 `rflex` payloads: constants and packed structs, field for field
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

struct RflexConfig {
  static constexpr std::string_view kWireName = "player_rflex_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t request = 0;  // driver-specific request code
  std::uint8_t value = 0;  // argument

  static constexpr auto fields() {
    return std::tuple{field("request", &RflexConfig::request),
                      field("value", &RflexConfig::value)};
  }
  friend bool operator==(const RflexConfig&, const RflexConfig&) = default;
};

}  // namespace playerkit::protocol
