#pragma once
// Player 1.5 `gripper` payloads: constants and packed structs, field for field
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

struct GripperData {
  static constexpr std::string_view kWireName = "player_gripper_data_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t state = 0;  // paddle/lift state bit field (see constants)
  std::uint8_t beams = 0;  // break-beam/limit bit field

  static constexpr auto fields() {
    return std::tuple{field("state", &GripperData::state),
                      field("beams", &GripperData::beams)};
  }
  friend bool operator==(const GripperData&, const GripperData&) = default;
};

struct GripperCommand {
  static constexpr std::string_view kWireName = "player_gripper_cmd_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t cmd = 0;  // gripper command byte (Pioneer gripper command set)
  std::uint8_t arg = 0;  // argument for commands that take one

  static constexpr auto fields() {
    return std::tuple{field("cmd", &GripperCommand::cmd),
                      field("arg", &GripperCommand::arg)};
  }
  friend bool operator==(const GripperCommand&, const GripperCommand&) = default;
};

}  // namespace playerkit::protocol
