#include "families/amtecpowercube/protocol/powercube_units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::hardware::powercube {

double normalized_radians(double radians) { return std::atan2(std::sin(radians), std::cos(radians)); }

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

double player_pan_degrees(double module_radians) { return -degrees(normalized_radians(module_radians)); }
double pan_module_radians(double player_degrees) { return radians(-player_degrees); }

std::uint16_t step_milliseconds(double distance_degrees, double speed_degrees_per_second) {
  if (speed_degrees_per_second <= 0) return 0;
  const double ms = std::rint(std::fabs(distance_degrees) / speed_degrees_per_second * 1000.0);
  return static_cast<std::uint16_t>(std::clamp(ms, 0.0, 65535.0));
}

std::int16_t wire_degrees(double degrees) {
  return static_cast<std::int16_t>(std::clamp(std::lround(degrees), -32768L, 32767L));
}

}  // namespace playerkit::hardware::powercube
