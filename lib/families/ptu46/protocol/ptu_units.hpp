#pragma once
// Degrees on the Player side, positions on the unit's (ptu46.md §2.1): a
// resolution in arc-seconds per position, demands truncated toward zero,
// readings rounded to the nearest degree for Player 1.5's int16 fields.
// Worked example of the sheet (PTU-46-17.5, 185.1428"): 30 deg -> 583
// positions; 583 positions -> 30 deg; 50 deg/s -> 972 positions/s.

#include <cstdint>

namespace playerkit::hardware::ptu46 {

// Degrees per position from the unit's `PR`/`TR` answer; 0 when the answer
// is not positive (the driver then resets the unit).
[[nodiscard]] double degrees_per_position(double arc_seconds_per_position);

// A demand in degrees (or degrees/s) as positions, truncated toward zero.
[[nodiscard]] std::int64_t positions_from_degrees(double degrees, double degrees_per_position);

// A reading in positions as degrees.
[[nodiscard]] double degrees_from_positions(double positions, double degrees_per_position);

}  // namespace playerkit::hardware::ptu46
