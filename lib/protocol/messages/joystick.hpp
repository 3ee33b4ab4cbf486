#pragma once
// Player 1.5 `joystick` payloads: constants and packed structs, field for field
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

struct JoystickData {
  static constexpr std::string_view kWireName = "player_joystick_data_t";
  static constexpr std::size_t kWireSize = 4;

  std::uint8_t xpos = 0;  // raw x
  std::uint8_t ypos = 0;  // raw y
  std::uint8_t button0 = 0;  // button 0 state
  std::uint8_t button1 = 0;  // button 1 state

  static constexpr auto fields() {
    return std::tuple{field("xpos", &JoystickData::xpos),
                      field("ypos", &JoystickData::ypos),
                      field("button0", &JoystickData::button0),
                      field("button1", &JoystickData::button1)};
  }
  friend bool operator==(const JoystickData&, const JoystickData&) = default;
};

}  // namespace playerkit::protocol
