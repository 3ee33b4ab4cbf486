#pragma once
// A GPS fix in SI units; latitude and longitude stay in degrees, as
// coordinates are read everywhere (protocol/si_units.hpp makes the same choice).

#include <cstdint>

#include "protocol/messages/gps.hpp"

namespace playerkit::client {

struct GpsFix {
  double time = 0;       // s since the epoch (UTC), time_sec + time_usec
  double latitude = 0;   // deg, north positive
  double longitude = 0;  // deg, east positive
  double altitude = 0;   // m
  double utm_easting = 0;   // m
  double utm_northing = 0;  // m
  std::uint8_t quality = 0;     // 0 invalid, 1 GPS fix, 2 DGPS fix
  std::uint8_t satellites = 0;  // in view
  double hdop = 0;              // plain HDOP (the wire carries it times 10)
  double horizontal_error = 0;  // m
  double vertical_error = 0;    // m
};

GpsFix to_si(const protocol::GpsData& data);

}  // namespace playerkit::client
