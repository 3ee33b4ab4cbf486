#pragma once
// A laser scan as the filter receives it, and the subsampled, precomputed
// form both laser models read: per beam its range, its angle in the robot
// frame with sine and cosine, and its endpoint in the robot frame — so the
// per-particle loops do no trigonometry beyond one sin/cos of the particle.

#include "algorithms/geometry/pose2.hpp"

#include <cstddef>
#include <vector>

namespace playerkit::amcl {

struct LaserScan {                 // one scan, in the robot frame
  std::vector<double> ranges;      // metres
  std::vector<double> bearings;    // radians, laser frame, same size as ranges
  double min_range = 0.0, max_range = 8.0;  // readings >= max_range are "no return"
  geometry::Pose2 sensor_pose;     // laser pose in the robot frame
};

struct PreparedBeams {
  double max_range = 0.0;
  geometry::Pose2 sensor_pose;
  std::vector<double> ranges;       // no-return beams hold max_range
  std::vector<double> robot_angle;  // sensor yaw + bearing
  std::vector<double> cos_angle, sin_angle;
  std::vector<double> end_x, end_y;  // beam endpoint in the robot frame
  std::vector<unsigned char> no_return;
  std::size_t size() const { return ranges.size(); }
};

// A reading the laser models can use: finite bearing, a range that is not
// NaN and not below min_range (at or above max_range it is a no-return).
bool usable_reading(const LaserScan& scan, std::size_t index);

// Keeps at most `max_beams` readings, evenly spread over the scan (first and
// last included), skipping readings that are not finite or below min_range,
// and those `left_out` marks (one flag per reading, when given). Reuses
// `out`'s storage. Throws std::invalid_argument if ranges and bearings (or
// left_out) differ in size.
void prepare_beams(const LaserScan& scan, std::size_t max_beams, PreparedBeams& out,
                   const std::vector<unsigned char>* left_out = nullptr);

}  // namespace playerkit::amcl
