#pragma once
// A base's odometry as the position interface's data (wire-format.md §5
// "position"): x, y in mm, yaw in whole degrees in the range the driver's
// 1.5 counterpart used, speeds in mm/s and deg/s, all rounded.

#include "algorithms/geometry/pose2.hpp"
#include "interfaces/wire_units.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::interfaces {

// `pose` in m, m, rad; `velocity` in m/s (forward, left) and rad/s.
[[nodiscard]] protocol::PositionData position_data(const geometry::Pose2& pose, const geometry::Pose2& velocity,
                                                   bool stalled, HeadingRange heading_range);

}  // namespace playerkit::interfaces
