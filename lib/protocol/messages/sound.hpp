#pragma once
// Player 1.5 `sound` payloads: constants and packed structs, field for field
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

struct SoundCommand {
  static constexpr std::string_view kWireName = "player_sound_cmd_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint16_t index = 0;  // index of the stored sound to play

  static constexpr auto fields() {
    return std::tuple{field("index", &SoundCommand::index)};
  }
  friend bool operator==(const SoundCommand&, const SoundCommand&) = default;
};

}  // namespace playerkit::protocol
