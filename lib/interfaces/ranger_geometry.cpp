#include "interfaces/ranger_geometry.hpp"

#include <algorithm>

#include "interfaces/wire_units.hpp"

namespace playerkit::interfaces {

std::array<std::int16_t, 3> wire_pose(const geometry::Pose2& pose) {
  return {wire_value<std::int16_t>(pose.x * kMillimetresPerMetre),
          wire_value<std::int16_t>(pose.y * kMillimetresPerMetre), wire_value<std::int16_t>(degrees(pose.yaw))};
}

protocol::SonarGeom sonar_geometry_reply(std::span<const geometry::Pose2> transducers) {
  protocol::SonarGeom reply;
  reply.subtype = protocol::kSonarGetGeomReq;
  const std::size_t count = std::min(transducers.size(), protocol::kSonarMaxSamples);
  reply.pose_count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count; ++i) reply.poses[i] = wire_pose(transducers[i]);
  return reply;
}

protocol::IrPoseRequest ir_pose_reply(std::span<const geometry::Pose2> sensors) {
  protocol::IrPoseRequest reply;
  reply.subtype = protocol::kIrPoseReq;
  const std::size_t count = std::min(sensors.size(), protocol::kIrMaxSamples);
  reply.poses.pose_count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count; ++i) reply.poses.poses[i] = wire_pose(sensors[i]);
  return reply;
}

}  // namespace playerkit::interfaces
