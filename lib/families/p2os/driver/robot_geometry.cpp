#include "families/p2os/driver/robot_geometry.hpp"

#include <algorithm>

#include "interfaces/ranger_geometry.hpp"
#include "interfaces/wire_units.hpp"

namespace playerkit::drivers::p2os {

interfaces::BaseGeometry base_geometry() { return {{-0.100, 0.0, 0.0}, 0.500, 0.450}; }

protocol::PositionGeom position_geometry() { return interfaces::position_geometry_reply(base_geometry()); }

std::vector<geometry::Pose2> sonar_poses(const hardware::p2os::RobotParams& params) {
  const auto count = static_cast<std::size_t>(
      std::clamp(params.sonar_count, 0, static_cast<int>(protocol::kSonarMaxSamples)));
  std::vector<geometry::Pose2> poses(count);
  const std::size_t known = std::min(count, params.sonar_poses.size());
  for (std::size_t i = 0; i < known; ++i) {
    const hardware::p2os::SonarPose& pose = params.sonar_poses[i];
    poses[i] = {pose.x / interfaces::kMillimetresPerMetre, pose.y / interfaces::kMillimetresPerMetre,
                interfaces::radians(pose.heading)};
  }
  return poses;
}

protocol::SonarGeom sonar_geometry(const hardware::p2os::RobotParams& params) {
  return interfaces::sonar_geometry_reply(sonar_poses(params));
}

}  // namespace playerkit::drivers::p2os
