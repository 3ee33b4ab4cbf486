#pragma once
// Player 1.5 `audiomixer` payloads: constants and packed structs, field for field
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

inline constexpr std::uint8_t kAudiomixerSetMaster = 1;  // mixer command channel: master
inline constexpr std::uint8_t kAudiomixerSetPcm = 2;  // channel: PCM
inline constexpr std::uint8_t kAudiomixerSetLine = 3;  // channel: line in
inline constexpr std::uint8_t kAudiomixerSetMic = 4;  // channel: microphone
inline constexpr std::uint8_t kAudiomixerSetIgain = 5;  // channel: input gain
inline constexpr std::uint8_t kAudiomixerSetOgain = 6;  // channel: output gain

struct AudioMixerConfig {
  static constexpr std::string_view kWireName = "player_audiomixer_config_t";
  static constexpr std::size_t kWireSize = 21;

  std::uint8_t subtype = 0;  // request subtype (reply carries current levels)
  std::uint16_t masterLeft = 0;  // master volume left
  std::uint16_t masterRight = 0;  // master volume right
  std::uint16_t pcmLeft = 0;  // PCM left
  std::uint16_t pcmRight = 0;  // PCM right
  std::uint16_t lineLeft = 0;  // line-in left
  std::uint16_t lineRight = 0;  // line-in right
  std::uint16_t micLeft = 0;  // mic left
  std::uint16_t micRight = 0;  // mic right
  std::uint16_t iGain = 0;  // input gain
  std::uint16_t oGain = 0;  // output gain

  static constexpr auto fields() {
    return std::tuple{field("subtype", &AudioMixerConfig::subtype),
                      field("masterLeft", &AudioMixerConfig::masterLeft),
                      field("masterRight", &AudioMixerConfig::masterRight),
                      field("pcmLeft", &AudioMixerConfig::pcmLeft),
                      field("pcmRight", &AudioMixerConfig::pcmRight),
                      field("lineLeft", &AudioMixerConfig::lineLeft),
                      field("lineRight", &AudioMixerConfig::lineRight),
                      field("micLeft", &AudioMixerConfig::micLeft),
                      field("micRight", &AudioMixerConfig::micRight),
                      field("iGain", &AudioMixerConfig::iGain),
                      field("oGain", &AudioMixerConfig::oGain)};
  }
  friend bool operator==(const AudioMixerConfig&, const AudioMixerConfig&) = default;
};

struct AudioMixerCommand {
  static constexpr std::string_view kWireName = "player_audiomixer_cmd_t";
  static constexpr std::size_t kWireSize = 5;

  std::uint8_t subtype = 0;  // PLAYER_AUDIOMIXER_SET_* (1..6) channel selector
  std::uint16_t left = 0;  // left level
  std::uint16_t right = 0;  // right level

  static constexpr auto fields() {
    return std::tuple{field("subtype", &AudioMixerCommand::subtype),
                      field("left", &AudioMixerCommand::left),
                      field("right", &AudioMixerCommand::right)};
  }
  friend bool operator==(const AudioMixerCommand&, const AudioMixerCommand&) = default;
};

}  // namespace playerkit::protocol
