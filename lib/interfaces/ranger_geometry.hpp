#pragma once
// Where a sonar ring's transducers or an IR array's sensors sit on the
// robot, as the GET_GEOM replies carry them (wire-format.md §5 "sonar" and
// "ir"): per sensor x mm, y mm, yaw degrees as int16, rounded and clamped.
// A sonar reply holds at most 64 poses, an IR one 32: the rest are dropped,
// and the struct's unused entries are zeros (1.5's p2os sent memory read
// past its table there, p2os.md §4.3).

#include <span>

#include "algorithms/geometry/pose2.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::interfaces {

// Poses in the robot's frame: m, m, rad.
[[nodiscard]] protocol::SonarGeom sonar_geometry_reply(std::span<const geometry::Pose2> transducers);
[[nodiscard]] protocol::IrPoseRequest ir_pose_reply(std::span<const geometry::Pose2> sensors);

// One pose in the wire's units.
[[nodiscard]] std::array<std::int16_t, 3> wire_pose(const geometry::Pose2& pose);

}  // namespace playerkit::interfaces
