#pragma once
// Player 1.5 `simulation` payloads: constants and packed structs, field for field
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

struct SimulationData {
  static constexpr std::string_view kWireName = "player_simulation_data_t";
  static constexpr std::size_t kWireSize = 1;

  std::uint8_t data = 0;  // placeholder byte

  static constexpr auto fields() {
    return std::tuple{field("data", &SimulationData::data)};
  }
  friend bool operator==(const SimulationData&, const SimulationData&) = default;
};

struct SimulationCommand {
  static constexpr std::string_view kWireName = "player_simulation_cmd_t";
  static constexpr std::size_t kWireSize = 1;

  std::uint8_t cmd = 0;  // placeholder byte

  static constexpr auto fields() {
    return std::tuple{field("cmd", &SimulationCommand::cmd)};
  }
  friend bool operator==(const SimulationCommand&, const SimulationCommand&) = default;
};

}  // namespace playerkit::protocol
