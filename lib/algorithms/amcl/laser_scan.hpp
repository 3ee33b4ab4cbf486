#pragma once
// A laser scan as the filter receives it, and the subsampled, precomputed
// form both laser models read: per beam its range, its angle in the robot
// frame with sine and cosine, and its endpoint in the robot frame — so the
// per-particle loops do no trigonometry beyond one sin/cos of the particle.

#include "algorithms/geometry/pose2.hpp"

#include <algorithm>
#include <cmath>
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

// Calls visit(i) for at most `most` of the readings `take(i)` accepts,
// evenly spread over them (first and last included), in order.
template <typename Take, typename Visit>
void for_each_spread_reading(std::size_t readings, std::size_t most, Take&& take, Visit&& visit) {
  std::size_t taken_count = 0;
  for (std::size_t i = 0; i < readings; ++i) taken_count += take(i) ? 1 : 0;
  if (taken_count == 0 || most == 0) return;
  const std::size_t kept = std::min(most, taken_count);
  const double step =
      kept > 1 ? static_cast<double>(taken_count - 1) / static_cast<double>(kept - 1) : 0.0;
  std::size_t taken_index = 0;
  std::size_t next = 0;
  for (std::size_t i = 0; i < readings && next < kept; ++i) {
    if (!take(i)) continue;
    const auto wanted = static_cast<std::size_t>(std::lround(static_cast<double>(next) * step));
    if (taken_index++ != wanted) continue;
    ++next;
    visit(i);
  }
}

// Keeps at most `max_beams` readings, evenly spread over the scan (first and
// last included), skipping readings that are not finite or below min_range,
// and those `left_out` marks (one flag per reading, when given). Reuses
// `out`'s storage. Throws std::invalid_argument if ranges and bearings (or
// left_out) differ in size.
void prepare_beams(const LaserScan& scan, std::size_t max_beams, PreparedBeams& out,
                   const std::vector<unsigned char>* left_out = nullptr);

}  // namespace playerkit::amcl
