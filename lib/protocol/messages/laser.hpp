#pragma once
// Player 1.5 `laser` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kLaserMaxSamples = 401;  // capacity of laser range/intensity arrays
inline constexpr std::uint8_t kLaserGetGeom = 1;  // get laser pose/size
inline constexpr std::uint8_t kLaserSetConfig = 2;  // set scan parameters
inline constexpr std::uint8_t kLaserGetConfig = 3;  // read scan parameters
inline constexpr std::uint8_t kLaserPowerConfig = 4;  // laser power on/off

struct LaserData {
  static constexpr std::string_view kWireName = "player_laser_data_t";
  static constexpr std::size_t kWireSize = 1213;

  std::int16_t min_angle = 0;  // first beam angle, 0.01 deg
  std::int16_t max_angle = 0;  // last beam angle, 0.01 deg
  std::uint16_t resolution = 0;  // angular step, 0.01 deg
  std::uint16_t range_res = 0;  // multiplier for ranges (1, 10, 100)
  std::uint16_t range_count = 0;  // number of valid readings
  std::array<std::uint16_t, 401> ranges{};  // ranges in mm (times range_res)
  std::array<std::uint8_t, 401> intensity{};  // reflectance value per reading

  static constexpr auto fields() {
    return std::tuple{field("min_angle", &LaserData::min_angle),
                      field("max_angle", &LaserData::max_angle),
                      field("resolution", &LaserData::resolution),
                      field("range_res", &LaserData::range_res),
                      field("range_count", &LaserData::range_count),
                      counted("ranges", &LaserData::ranges, &LaserData::range_count),
                      counted("intensity", &LaserData::intensity, &LaserData::range_count)};
  }
  friend bool operator==(const LaserData&, const LaserData&) = default;
};

struct LaserGeom {
  static constexpr std::string_view kWireName = "player_laser_geom_t";
  static constexpr std::size_t kWireSize = 11;

  std::uint8_t subtype = 0;  // PLAYER_LASER_GET_GEOM (1)
  std::array<std::int16_t, 3> pose{};  // laser pose in robot frame: x mm, y mm, yaw deg
  std::array<std::int16_t, 2> size{};  // laser size: mm, mm

  static constexpr auto fields() {
    return std::tuple{field("subtype", &LaserGeom::subtype),
                      field("pose", &LaserGeom::pose),
                      field("size", &LaserGeom::size)};
  }
  friend bool operator==(const LaserGeom&, const LaserGeom&) = default;
};

struct LaserConfig {
  static constexpr std::string_view kWireName = "player_laser_config_t";
  static constexpr std::size_t kWireSize = 10;

  std::uint8_t subtype = 0;  // PLAYER_LASER_SET_CONFIG (2) or _GET_CONFIG (3)
  std::int16_t min_angle = 0;  // scan start, 0.01 deg (-9000..9000)
  std::int16_t max_angle = 0;  // scan end, 0.01 deg
  std::uint16_t resolution = 0;  // angular step, 0.01 deg (25, 50, 100)
  std::uint16_t range_res = 0;  // range unit: 1 mm, 10 cm, 100 dm
  std::uint8_t intensity = 0;  // non-zero to request intensity data

  static constexpr auto fields() {
    return std::tuple{field("subtype", &LaserConfig::subtype),
                      field("min_angle", &LaserConfig::min_angle),
                      field("max_angle", &LaserConfig::max_angle),
                      field("resolution", &LaserConfig::resolution),
                      field("range_res", &LaserConfig::range_res),
                      field("intensity", &LaserConfig::intensity)};
  }
  friend bool operator==(const LaserConfig&, const LaserConfig&) = default;
};

struct LaserPowerConfig {
  static constexpr std::string_view kWireName = "player_laser_power_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t subtype = 0;  // PLAYER_LASER_POWER_CONFIG (4)
  std::uint8_t value = 0;  // 0 = off, 1 = on

  static constexpr auto fields() {
    return std::tuple{field("subtype", &LaserPowerConfig::subtype),
                      field("value", &LaserPowerConfig::value)};
  }
  friend bool operator==(const LaserPowerConfig&, const LaserPowerConfig&) = default;
};

}  // namespace playerkit::protocol
