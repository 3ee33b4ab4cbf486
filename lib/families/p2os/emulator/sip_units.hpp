#pragma once
// World quantities in a SIP's raw units for one parameter row, with the
// wrap-around of p2os.md §6.8: positions and heading modulo one turn of the
// 12-bit counters (4096; 1024 heading units on Pioneer 1 rows).

#include "families/p2os/protocol/robot_params.hpp"

#include <cstdint>

namespace playerkit::emulators::p2os {

inline constexpr int kPositionUnitsWrap = 4096;

// XPOS/YPOS: round(metres × 1000 / DistConvFactor) mod 4096.
std::uint16_t position_units(double metres, const hardware::p2os::RobotParams& params);
// THPOS: round(θ / AngleConvFactor) mod units per turn.
std::int16_t heading_units(double radians, const hardware::p2os::RobotParams& params);
// L/R VEL: round(mm/s / VelConvFactor), saturated to 16 bits.
std::int16_t velocity_units(double metres_per_second, const hardware::p2os::RobotParams& params);
// Sonar RANGE: round(mm / RangeConvFactor), saturated.
std::uint16_t range_units(double metres, const hardware::p2os::RobotParams& params);

}  // namespace playerkit::emulators::p2os
