#pragma once
// Player 1.5 `audiodsp` payloads: constants and packed structs, field for field
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

inline constexpr std::uint8_t kAudiodspSetConfig = 1;  // set sampling configuration
inline constexpr std::uint8_t kAudiodspGetConfig = 2;  // read sampling configuration
inline constexpr std::uint8_t kAudiodspPlayTone = 3;  // command subtype: play a tone
inline constexpr std::uint8_t kAudiodspPlayChirp = 4;  // command subtype: play a BPSK chirp
inline constexpr std::uint8_t kAudiodspReplay = 5;  // command subtype: replay last sound

struct AudioDspData {
  static constexpr std::string_view kWireName = "player_audiodsp_data_t";
  static constexpr std::size_t kWireSize = 20;

  std::array<std::uint16_t, 5> freq{};  // 5 peak frequencies, Hz
  std::array<std::uint16_t, 5> amp{};  // 5 peak amplitudes (dB?)

  static constexpr auto fields() {
    return std::tuple{field("freq", &AudioDspData::freq),
                      field("amp", &AudioDspData::amp)};
  }
  friend bool operator==(const AudioDspData&, const AudioDspData&) = default;
};

struct AudioDspCommand {
  static constexpr std::string_view kWireName = "player_audiodsp_cmd_t";
  static constexpr std::size_t kWireSize = 75;

  std::uint8_t subtype = 0;  // PLAYER_AUDIODSP_PLAY_TONE (3), _PLAY_CHIRP (4) or _REPLAY (5)
  std::uint16_t frequency = 0;  // Hz
  std::uint16_t amplitude = 0;  // dB?
  std::uint32_t duration = 0;  // ms
  std::array<std::uint8_t, 64> bitString{};  // bits to encode in a chirp
  std::uint16_t bitStringLen = 0;  // number of valid bytes in bitString

  static constexpr auto fields() {
    return std::tuple{field("subtype", &AudioDspCommand::subtype),
                      field("frequency", &AudioDspCommand::frequency),
                      field("amplitude", &AudioDspCommand::amplitude),
                      field("duration", &AudioDspCommand::duration),
                      counted("bitString", &AudioDspCommand::bitString, &AudioDspCommand::bitStringLen),
                      field("bitStringLen", &AudioDspCommand::bitStringLen)};
  }
  friend bool operator==(const AudioDspCommand&, const AudioDspCommand&) = default;
};

struct AudioDspConfig {
  static constexpr std::string_view kWireName = "player_audiodsp_config_t";
  static constexpr std::size_t kWireSize = 6;

  std::uint8_t subtype = 0;  // PLAYER_AUDIODSP_SET_CONFIG (1) or _GET_CONFIG (2)
  std::int16_t sampleFormat = 0;  // OSS sample format code
  std::uint16_t sampleRate = 0;  // sample rate, Hz
  std::uint8_t channels = 0;  // 1 mono, 2 stereo

  static constexpr auto fields() {
    return std::tuple{field("subtype", &AudioDspConfig::subtype),
                      field("sampleFormat", &AudioDspConfig::sampleFormat),
                      field("sampleRate", &AudioDspConfig::sampleRate),
                      field("channels", &AudioDspConfig::channels)};
  }
  friend bool operator==(const AudioDspConfig&, const AudioDspConfig&) = default;
};

}  // namespace playerkit::protocol
