#pragma once
// Player 1.5 `bumper` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kBumperMaxSamples = 32;  // capacity of bumper arrays
inline constexpr std::uint8_t kBumperGetGeomReq = 1;  // get bumper geometry

struct BumperData {
  static constexpr std::string_view kWireName = "player_bumper_data_t";
  static constexpr std::size_t kWireSize = 33;

  std::uint8_t bumper_count = 0;  // number of valid bumpers
  std::array<std::uint8_t, 32> bumpers{};  // per-bumper state, non-zero = pressed

  static constexpr auto fields() {
    return std::tuple{field("bumper_count", &BumperData::bumper_count),
                      counted("bumpers", &BumperData::bumpers, &BumperData::bumper_count)};
  }
  friend bool operator==(const BumperData&, const BumperData&) = default;
};

struct BumperDefine {
  static constexpr std::string_view kWireName = "player_bumper_define_t";
  static constexpr std::size_t kWireSize = 10;

  std::int16_t x_offset = 0;  // bumper centre x, mm
  std::int16_t y_offset = 0;  // bumper centre y, mm
  std::int16_t th_offset = 0;  // bumper orientation, degrees
  std::uint16_t length = 0;  // bumper length, mm
  std::uint16_t radius = 0;  // radius of curvature, mm (0 = straight)

  static constexpr auto fields() {
    return std::tuple{field("x_offset", &BumperDefine::x_offset),
                      field("y_offset", &BumperDefine::y_offset),
                      field("th_offset", &BumperDefine::th_offset),
                      field("length", &BumperDefine::length),
                      field("radius", &BumperDefine::radius)};
  }
  friend bool operator==(const BumperDefine&, const BumperDefine&) = default;
};

struct BumperGeom {
  static constexpr std::string_view kWireName = "player_bumper_geom_t";
  static constexpr std::size_t kWireSize = 323;

  std::uint8_t subtype = 0;  // PLAYER_BUMPER_GET_GEOM_REQ (1)
  std::uint16_t bumper_count = 0;  // number of valid definitions
  std::array<BumperDefine, 32> bumper_def{};  // per-bumper geometry (10 bytes each)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &BumperGeom::subtype),
                      field("bumper_count", &BumperGeom::bumper_count),
                      counted("bumper_def", &BumperGeom::bumper_def, &BumperGeom::bumper_count)};
  }
  friend bool operator==(const BumperGeom&, const BumperGeom&) = default;
};

}  // namespace playerkit::protocol
