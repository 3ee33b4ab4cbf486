#pragma once
// Player 1.5 `audio` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kAudioDataBufferSize = 20;  // audio data packet bytes
inline constexpr std::size_t kAudioCommandBufferSize = 6;  // audio command bytes (3 shorts)

struct AudioData {
  static constexpr std::string_view kWireName = "player_audio_data_t";
  static constexpr std::size_t kWireSize = 20;

  std::uint16_t frequency0 = 0;  // peak 0 frequency (Hz)
  std::uint16_t amplitude0 = 0;  // peak 0 amplitude (dB?)
  std::uint16_t frequency1 = 0;  // peak 1 frequency
  std::uint16_t amplitude1 = 0;  // peak 1 amplitude
  std::uint16_t frequency2 = 0;  // peak 2 frequency
  std::uint16_t amplitude2 = 0;  // peak 2 amplitude
  std::uint16_t frequency3 = 0;  // peak 3 frequency
  std::uint16_t amplitude3 = 0;  // peak 3 amplitude
  std::uint16_t frequency4 = 0;  // peak 4 frequency
  std::uint16_t amplitude4 = 0;  // peak 4 amplitude

  static constexpr auto fields() {
    return std::tuple{field("frequency0", &AudioData::frequency0),
                      field("amplitude0", &AudioData::amplitude0),
                      field("frequency1", &AudioData::frequency1),
                      field("amplitude1", &AudioData::amplitude1),
                      field("frequency2", &AudioData::frequency2),
                      field("amplitude2", &AudioData::amplitude2),
                      field("frequency3", &AudioData::frequency3),
                      field("amplitude3", &AudioData::amplitude3),
                      field("frequency4", &AudioData::frequency4),
                      field("amplitude4", &AudioData::amplitude4)};
  }
  friend bool operator==(const AudioData&, const AudioData&) = default;
};

struct AudioCommand {
  static constexpr std::string_view kWireName = "player_audio_cmd_t";
  static constexpr std::size_t kWireSize = 6;

  std::uint16_t frequency = 0;  // tone frequency (Hz)
  std::uint16_t amplitude = 0;  // tone amplitude (dB?)
  std::uint16_t duration = 0;  // tone duration (units not fixed)

  static constexpr auto fields() {
    return std::tuple{field("frequency", &AudioCommand::frequency),
                      field("amplitude", &AudioCommand::amplitude),
                      field("duration", &AudioCommand::duration)};
  }
  friend bool operator==(const AudioCommand&, const AudioCommand&) = default;
};

}  // namespace playerkit::protocol
