#pragma once
// Player 1.5 `speech` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kSpeechMaxStringLen = 256;  // speech command length
inline constexpr std::size_t kSpeechMaxQueueLen = 4;  // driver-side queue depth for speech commands

struct SpeechCommand {
  static constexpr std::string_view kWireName = "player_speech_cmd_t";
  static constexpr std::size_t kWireSize = 256;

  FixedString<256> string{};  // ASCII text to speak

  static constexpr auto fields() {
    return std::tuple{field("string", &SpeechCommand::string)};
  }
  friend bool operator==(const SpeechCommand&, const SpeechCommand&) = default;
};

}  // namespace playerkit::protocol
