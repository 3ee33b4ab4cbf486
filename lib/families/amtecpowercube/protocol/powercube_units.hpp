#pragma once
// Module angles (radians, the pan module counting clockwise) and Player's
// (degrees, counter-clockwise), amtecpowercube.md §3.

#include <cstdint>

namespace playerkit::hardware::powercube {

// Into (-pi, pi]: a pan module may have turned past half a circle.
[[nodiscard]] double normalized_radians(double radians);

// Player's pan in degrees for a pan module position, rounded (1.5 truncated).
[[nodiscard]] double player_pan_degrees(double module_radians);
// A Player pan demand (degrees) as a pan module position (radians).
[[nodiscard]] double pan_module_radians(double player_degrees);

[[nodiscard]] double degrees(double radians);
[[nodiscard]] double radians(double degrees);

// How long a step of `distance` degrees takes at `speed` deg/s, in the
// uint16 milliseconds SET_MOTION carries (a longer one is cut to 65535).
[[nodiscard]] std::uint16_t step_milliseconds(double distance_degrees, double speed_degrees_per_second);

// A reading in whole degrees for the int16 fields of player_ptz_data_t.
[[nodiscard]] std::int16_t wire_degrees(double degrees);

}  // namespace playerkit::hardware::powercube
