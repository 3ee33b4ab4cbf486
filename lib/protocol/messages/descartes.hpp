#pragma once
// Player 1.5 `descartes` payloads: constants and packed structs, field for field
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

struct DescartesConfig {
  static constexpr std::string_view kWireName = "player_descartes_config_t";
  static constexpr std::size_t kWireSize = 6;

  std::int16_t speed = 0;  // mm/s
  std::int16_t heading = 0;  // degrees
  std::int16_t distance = 0;  // mm

  static constexpr auto fields() {
    return std::tuple{field("speed", &DescartesConfig::speed),
                      field("heading", &DescartesConfig::heading),
                      field("distance", &DescartesConfig::distance)};
  }
  friend bool operator==(const DescartesConfig&, const DescartesConfig&) = default;
};

struct DescartesData {
  static constexpr std::string_view kWireName = "player_descartes_data_t";
  static constexpr std::size_t kWireSize = 12;

  std::int32_t xpos = 0;  // x, mm
  std::int32_t ypos = 0;  // y, mm
  std::int16_t theta = 0;  // heading, degrees
  std::array<std::uint8_t, 2> bumpers{};  // two bumper booleans

  static constexpr auto fields() {
    return std::tuple{field("xpos", &DescartesData::xpos),
                      field("ypos", &DescartesData::ypos),
                      field("theta", &DescartesData::theta),
                      field("bumpers", &DescartesData::bumpers)};
  }
  friend bool operator==(const DescartesData&, const DescartesData&) = default;
};

}  // namespace playerkit::protocol
