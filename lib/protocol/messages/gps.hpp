#pragma once
// Player 1.5 `gps` payloads: constants and packed structs, field for field
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

struct GpsData {
  static constexpr std::string_view kWireName = "player_gps_data_t";
  static constexpr std::size_t kWireSize = 40;

  std::uint32_t time_sec = 0;  // GPS (UTC) time, seconds since epoch
  std::uint32_t time_usec = 0;  // GPS time, microseconds
  std::int32_t latitude = 0;  // 1/60 arc-second units (1/216000 deg), north positive
  std::int32_t longitude = 0;  // 1/60 arc-second units, east positive
  std::int32_t altitude = 0;  // mm above reference
  std::int32_t utm_e = 0;  // UTM easting, cm
  std::int32_t utm_n = 0;  // UTM northing, cm
  std::uint8_t quality = 0;  // 0 invalid, 1 GPS fix, 2 DGPS fix
  std::uint8_t num_sats = 0;  // satellites in view
  std::uint16_t hdop = 0;  // HDOP times 10
  std::uint32_t err_horz = 0;  // horizontal error, mm
  std::uint32_t err_vert = 0;  // vertical error, mm

  static constexpr auto fields() {
    return std::tuple{field("time_sec", &GpsData::time_sec),
                      field("time_usec", &GpsData::time_usec),
                      field("latitude", &GpsData::latitude),
                      field("longitude", &GpsData::longitude),
                      field("altitude", &GpsData::altitude),
                      field("utm_e", &GpsData::utm_e),
                      field("utm_n", &GpsData::utm_n),
                      field("quality", &GpsData::quality),
                      field("num_sats", &GpsData::num_sats),
                      field("hdop", &GpsData::hdop),
                      field("err_horz", &GpsData::err_horz),
                      field("err_vert", &GpsData::err_vert)};
  }
  friend bool operator==(const GpsData&, const GpsData&) = default;
};

}  // namespace playerkit::protocol
