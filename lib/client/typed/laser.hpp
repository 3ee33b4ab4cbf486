#pragma once
// Laser scans, geometry and configuration in SI units.

#include <cstdint>
#include <vector>

#include "client/typed/pose.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::client {

struct LaserScan {
  double min_angle = 0;   // rad, bearing of the first beam
  double max_angle = 0;   // rad, bearing of the last beam
  double resolution = 0;  // rad between beams
  std::vector<double> ranges;             // m (wire mm times range_res; a range_res of 0 counts as 1)
  std::vector<double> bearings;           // rad, min_angle + i * resolution, as libplayerc computes them
  std::vector<std::uint8_t> intensities;  // as on the wire
};

struct LaserGeometry {
  Pose2D pose;        // in the robot frame
  double length = 0;  // m
  double width = 0;   // m
};

// The scan parameters of the get-config reply and the set-config request.
struct LaserConfig {
  double min_angle = 0;       // rad
  double max_angle = 0;       // rad
  double resolution = 0;      // rad (the SICK takes 0.25, 0.5 or 1 degree)
  std::uint16_t range_res = 1;  // range unit multiplier, as on the wire: 1 mm, 10, 100
  bool intensity = false;
};

LaserScan to_si(const protocol::LaserData& data);
LaserGeometry to_si(const protocol::LaserGeom& geom);
LaserConfig to_si(const protocol::LaserConfig& config);

// A set-config request: angles rounded to 0.01 degree and clamped to int16/uint16.
protocol::LaserConfig set_config_request(const LaserConfig& config);

}  // namespace playerkit::client
