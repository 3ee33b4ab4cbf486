#pragma once
// Player 1.5 `dio` payloads: constants and packed structs, field for field
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

struct DioData {
  static constexpr std::string_view kWireName = "player_dio_data_t";
  static constexpr std::size_t kWireSize = 5;

  std::uint8_t count = 0;  // number of valid input bits
  std::uint32_t digin = 0;  // input bit field

  static constexpr auto fields() {
    return std::tuple{field("count", &DioData::count),
                      field("digin", &DioData::digin)};
  }
  friend bool operator==(const DioData&, const DioData&) = default;
};

}  // namespace playerkit::protocol
