#include "algorithms/cspace/free_ranges.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace playerkit::cspace {

std::vector<double> free_ranges(std::span<const double> ranges, ScanGeometry geometry, double radius,
                                int obstacle_stride) {
  if (!(radius >= 0.0)) throw std::invalid_argument("cspace: the radius must be 0 or more");
  if (obstacle_stride < 1) throw std::invalid_argument("cspace: the obstacle stride must be 1 or more");
  const std::size_t count = ranges.size();
  std::vector<double> x(count);
  std::vector<double> y(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double bearing = geometry.first_bearing + static_cast<double>(i) * geometry.bearing_step;
    x[i] = ranges[i] * std::cos(bearing);
    y[i] = ranges[i] * std::sin(bearing);
  }
  const double radius_squared = radius * radius;
  const auto stride = static_cast<std::size_t>(obstacle_stride);
  std::vector<double> free(count, 0.0);
  for (std::size_t n = 0; n < count; ++n) {
    const double length = ranges[n];
    double reach = length - radius;
    const double length_squared = length * length;
    if (length_squared > 0.0) {
      for (std::size_t i = 0; i < count; i += stride) {
        // Its own return gives length - radius, already the start; computed,
        // rounding would take a micrometre off.
        if (i == n) continue;
        // A return whose own range less the radius is past the reach so far
        // cannot come closer along this beam.
        if (ranges[i] - radius > reach) continue;
        const double along = (x[n] * x[i] + y[n] * y[i]) / length_squared;  // fraction of beam n
        if (along < 0.0 || along > 1.0) continue;
        const double dx = along * x[n] - x[i];
        const double dy = along * y[n] - y[i];
        const double off_squared = dx * dx + dy * dy;
        if (off_squared > radius_squared) continue;
        // Where the beam enters the disc around the return.
        reach = std::min(reach, along * length - std::sqrt(radius_squared - off_squared));
      }
    }
    free[n] = std::max(reach, 0.0);
  }
  return free;
}

}  // namespace playerkit::cspace
