#pragma once
// Degrees as VFH counts them: 0..360, 90 straight ahead.

#include <cmath>
#include <numbers>

namespace playerkit::vfh {

inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

inline double wrap_degrees(double degrees) {
  degrees = std::fmod(degrees, 360.0);
  return degrees < 0 ? degrees + 360.0 : degrees;
}

}  // namespace playerkit::vfh
