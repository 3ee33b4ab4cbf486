#include "interfaces/wire_units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace playerkit::interfaces {

template <class T>
T wire_value(double value) {
  if (std::isnan(value)) return T{0};
  const double low = static_cast<double>(std::numeric_limits<T>::min());
  const double high = static_cast<double>(std::numeric_limits<T>::max());
  return static_cast<T>(std::clamp(std::round(value), low, high));
}

template std::int16_t wire_value<std::int16_t>(double);
template std::uint16_t wire_value<std::uint16_t>(double);
template std::int32_t wire_value<std::int32_t>(double);
template std::uint32_t wire_value<std::uint32_t>(double);

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

std::int32_t heading_degrees(double radians_value, HeadingRange range) {
  // Rounded before wrapping, so 359.6° is reported as 0 rather than 360.
  double whole = std::round(degrees(radians_value));
  if (!std::isfinite(whole)) return 0;
  whole = std::fmod(whole, 360.0);  // (-360, 360)
  if (range == HeadingRange::from_0_to_360) {
    if (whole < 0.0) whole += 360.0;
  } else {
    if (whole <= -180.0) whole += 360.0;
    if (whole > 180.0) whole -= 360.0;
  }
  return static_cast<std::int32_t>(whole);
}

}  // namespace playerkit::interfaces
