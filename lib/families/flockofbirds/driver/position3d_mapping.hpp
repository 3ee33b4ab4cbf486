#pragma once
// A bird's pose as Player's position3d data (flockofbirds.md §3), the axes
// as Player 1.5 mapped them: X and Y as the bird reports them, Z with its
// sign inverted; yaw the azimuth, pitch the elevation, roll the roll, each
// from 0 to 360 degrees (1.5 added 360 to negative angles), in arc-seconds.
// Values are rounded to the nearest unit (1.5 truncated); speeds are 0 (1.5
// left them uninitialised) and stall is 0.

#include "families/flockofbirds/protocol/bird_record.hpp"
#include "protocol/messages/position3d.hpp"

namespace playerkit::drivers::flockofbirds {

[[nodiscard]] protocol::Position3dData position3d_from_bird(const hardware::flockofbirds::BirdPose& pose);

// Degrees as arc-seconds in [0, 1296000), negative angles turned once.
[[nodiscard]] std::int32_t arc_seconds_0_to_360(double degrees);

}  // namespace playerkit::drivers::flockofbirds
