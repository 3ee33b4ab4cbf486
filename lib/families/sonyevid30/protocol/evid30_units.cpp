#include "families/sonyevid30/protocol/evid30_units.hpp"

#include <algorithm>
#include <cmath>

#include "families/sonyevid30/protocol/visca.hpp"

namespace playerkit::hardware::sonyevid30 {

int pan_units(double player_degrees) {
  const double camera_degrees = -std::clamp(player_degrees, -100.0, 100.0);
  return std::clamp(static_cast<int>(std::lround(camera_degrees * kPanUnitsPerDegree)), kPanMinUnits, kPanMaxUnits);
}

double pan_degrees(int camera_units) { return -camera_units / kPanUnitsPerDegree; }

int tilt_units(double degrees) {
  return std::clamp(static_cast<int>(std::lround(std::clamp(degrees, -25.0, 25.0) * kTiltUnitsPerDegree)),
                    kTiltMinUnits, kTiltMaxUnits);
}

double tilt_degrees(int camera_units) { return camera_units / kTiltUnitsPerDegree; }

// 1.5's mapping, 1024 steps from wide to tele (§3.2), rounded.
int zoom_units(double fov_degrees, FieldOfView limits) {
  const double units = 1024.0 * (fov_degrees - limits.wide) / (limits.tele - limits.wide);
  return static_cast<int>(std::clamp(std::lround(units), 0L, static_cast<long>(kZoomMaxUnits)));
}

double fov_degrees(int zoom_units, FieldOfView limits) {
  return limits.wide + zoom_units * (limits.tele - limits.wide) / 1024.0;
}

}  // namespace playerkit::hardware::sonyevid30
