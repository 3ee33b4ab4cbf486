#pragma once
// The RMP's status as Player data (segwayrmp.md §3): position,
// position3d and power, from one complete status set and the odometry.

#include "families/segwayrmp/protocol/rmp_frames.hpp"
#include "families/segwayrmp/protocol/rmp_odometry.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/position3d.hpp"
#include "protocol/messages/power.hpp"

namespace playerkit::drivers::segwayrmp {

inline constexpr double kArcSecondsPerDegree = 3600.0;

[[nodiscard]] protocol::PositionData position_data(const hardware::segwayrmp::Status& status,
                                                   const hardware::segwayrmp::OdometryPose& pose);
[[nodiscard]] protocol::Position3dData position3d_data(const hardware::segwayrmp::Status& status,
                                                       const hardware::segwayrmp::OdometryPose& pose);
[[nodiscard]] protocol::PowerData power_data(const hardware::segwayrmp::Status& status);

}  // namespace playerkit::drivers::segwayrmp
