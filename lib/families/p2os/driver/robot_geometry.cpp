#include "families/p2os/driver/robot_geometry.hpp"

#include <algorithm>

namespace playerkit::drivers::p2os {

protocol::PositionGeom position_geometry() {
  protocol::PositionGeom geometry;
  geometry.subtype = protocol::kPositionGetGeomReq;
  geometry.pose = {-100, 0, 0};
  geometry.size = {500, 450};
  return geometry;
}

protocol::SonarGeom sonar_geometry(const hardware::p2os::RobotParams& params) {
  protocol::SonarGeom geometry;
  geometry.subtype = protocol::kSonarGetGeomReq;
  const auto count = static_cast<std::size_t>(
      std::clamp(params.sonar_count, 0, static_cast<int>(protocol::kSonarMaxSamples)));
  geometry.pose_count = static_cast<std::uint16_t>(count);
  const std::size_t known = std::min(count, params.sonar_poses.size());
  for (std::size_t i = 0; i < known; ++i) {
    const hardware::p2os::SonarPose& pose = params.sonar_poses[i];
    geometry.poses[i] = {static_cast<std::int16_t>(pose.x), static_cast<std::int16_t>(pose.y),
                         static_cast<std::int16_t>(pose.heading)};
  }
  return geometry;
}

}  // namespace playerkit::drivers::p2os
