#pragma once
// Fiducial detections, detector geometry and field of view in SI units.

#include <cstdint>
#include <vector>

#include "client/typed/pose.hpp"
#include "protocol/messages/fiducial.hpp"

namespace playerkit::client {

struct Fiducial {
  std::int16_t id = -1;      // -1 when unidentified
  double range = 0;          // m
  double bearing = 0;        // rad
  double orientation = 0;    // rad
  double range_uncertainty = 0;        // m
  double bearing_uncertainty = 0;      // rad
  double orientation_uncertainty = 0;  // rad
};

struct FiducialGeometry {
  Pose2D pose;                // of the detector in the robot frame
  double length = 0;          // m, detector size
  double width = 0;           // m
  double marker_length = 0;   // m, fiducial size
  double marker_width = 0;    // m
};

struct FiducialFov {
  double min_range = 0;   // m
  double max_range = 0;   // m
  double view_angle = 0;  // rad
};

std::vector<Fiducial> to_si(const protocol::FiducialData& data);
FiducialGeometry to_si(const protocol::FiducialGeom& geom);
FiducialFov to_si(const protocol::FiducialFov& fov);
// A set-fov request: mm and whole degrees, rounded, clamped to uint16; NaN or infinity throws.
protocol::FiducialFov set_fov_request(const FiducialFov& fov);

}  // namespace playerkit::client
