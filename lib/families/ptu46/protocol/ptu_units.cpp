#include "families/ptu46/protocol/ptu_units.hpp"

#include <cmath>

namespace playerkit::hardware::ptu46 {

double degrees_per_position(double arc_seconds_per_position) {
  return arc_seconds_per_position > 0 ? arc_seconds_per_position / 3600.0 : 0.0;
}

std::int64_t positions_from_degrees(double degrees, double degrees_per_position) {
  if (degrees_per_position <= 0 || !std::isfinite(degrees)) return 0;
  return static_cast<std::int64_t>(std::trunc(degrees / degrees_per_position));
}

double degrees_from_positions(double positions, double degrees_per_position) {
  return positions * degrees_per_position;
}

}  // namespace playerkit::hardware::ptu46
