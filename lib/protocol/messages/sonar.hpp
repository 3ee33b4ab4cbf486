#pragma once
// Player 1.5 `sonar` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kSonarMaxSamples = 64;  // capacity of sonar range and pose arrays
inline constexpr std::uint8_t kSonarGetGeomReq = 1;  // get transducer poses
inline constexpr std::uint8_t kSonarPowerReq = 2;  // sonar power on/off

struct SonarData {
  static constexpr std::string_view kWireName = "player_sonar_data_t";
  static constexpr std::size_t kWireSize = 130;

  std::uint16_t range_count = 0;  // number of valid readings
  std::array<std::uint16_t, 64> ranges{};  // ranges, mm

  static constexpr auto fields() {
    return std::tuple{field("range_count", &SonarData::range_count),
                      counted("ranges", &SonarData::ranges, &SonarData::range_count)};
  }
  friend bool operator==(const SonarData&, const SonarData&) = default;
};

struct SonarGeom {
  static constexpr std::string_view kWireName = "player_sonar_geom_t";
  static constexpr std::size_t kWireSize = 387;

  std::uint8_t subtype = 0;  // PLAYER_SONAR_GET_GEOM_REQ (1)
  std::uint16_t pose_count = 0;  // number of valid poses
  std::array<std::array<std::int16_t, 3>, 64> poses{};  // per transducer: x mm, y mm, yaw deg (int16 each, 6 bytes per transducer)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &SonarGeom::subtype),
                      field("pose_count", &SonarGeom::pose_count),
                      counted("poses", &SonarGeom::poses, &SonarGeom::pose_count)};
  }
  friend bool operator==(const SonarGeom&, const SonarGeom&) = default;
};

struct SonarPowerConfig {
  static constexpr std::string_view kWireName = "player_sonar_power_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t subtype = 0;  // PLAYER_SONAR_POWER_REQ (2)
  std::uint8_t value = 0;  // 0 = off, non-zero = on

  static constexpr auto fields() {
    return std::tuple{field("subtype", &SonarPowerConfig::subtype),
                      field("value", &SonarPowerConfig::value)};
  }
  friend bool operator==(const SonarPowerConfig&, const SonarPowerConfig&) = default;
};

}  // namespace playerkit::protocol
