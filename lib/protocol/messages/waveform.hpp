#pragma once
// Player 1.5 `waveform` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kWaveformDataMax = 4096;  // capacity of waveform sample buffer

struct WaveformData {
  static constexpr std::string_view kWireName = "player_waveform_data_t";
  static constexpr std::size_t kWireSize = 4106;

  std::uint32_t rate = 0;  // bit rate, bits per second
  std::uint16_t depth = 0;  // bits per sample
  std::uint32_t samples = 0;  // number of bytes of raw data used
  std::array<std::uint8_t, 4096> data{};  // raw sample bytes

  static constexpr auto fields() {
    return std::tuple{field("rate", &WaveformData::rate),
                      field("depth", &WaveformData::depth),
                      field("samples", &WaveformData::samples),
                      counted("data", &WaveformData::data, &WaveformData::samples)};
  }
  friend bool operator==(const WaveformData&, const WaveformData&) = default;
};

}  // namespace playerkit::protocol
