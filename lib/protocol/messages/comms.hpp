#pragma once
// Player 1.5 `comms` payloads: constants and packed structs, field for field
// as in wire-format.md §5 (names, order, sizes). Values are in wire units.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <vector>

#include "protocol/fields.hpp"
#include "protocol/fixed_string.hpp"
#include "protocol/constants.hpp"

namespace playerkit::protocol {

// The struct names only the first byte; a comms payload is any number of bytes.
struct CommsData {
  static constexpr std::string_view kWireName = "player_comms_data_t";
  static constexpr std::size_t kWireSize = 1;

  std::vector<std::uint8_t> msg{};  // first byte of an opaque variable-length payload

  static constexpr auto fields() {
    return std::tuple{tail("msg", &CommsData::msg, 1, kMaxPayloadSize)};
  }
  friend bool operator==(const CommsData&, const CommsData&) = default;
};

// The struct names only the first byte; a comms payload is any number of bytes.
struct CommsCommand {
  static constexpr std::string_view kWireName = "player_comms_cmd_t";
  static constexpr std::size_t kWireSize = 1;

  std::vector<std::uint8_t> msg{};  // first byte of an opaque variable-length payload

  static constexpr auto fields() {
    return std::tuple{tail("msg", &CommsCommand::msg, 1, kMaxPayloadSize)};
  }
  friend bool operator==(const CommsCommand&, const CommsCommand&) = default;
};

}  // namespace playerkit::protocol
