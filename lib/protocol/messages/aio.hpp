#pragma once
// Player 1.5 `aio` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kAioMaxSamples = 8;  // capacity of analog input array

struct AioData {
  static constexpr std::string_view kWireName = "player_aio_data_t";
  static constexpr std::size_t kWireSize = 33;

  std::uint8_t count = 0;  // number of valid samples
  std::array<std::int32_t, 8> anin{};  // analog samples (driver units)

  static constexpr auto fields() {
    return std::tuple{field("count", &AioData::count),
                      counted("anin", &AioData::anin, &AioData::count)};
  }
  friend bool operator==(const AioData&, const AioData&) = default;
};

}  // namespace playerkit::protocol
