#include "families/p2os/emulator/sonar_array.hpp"

#include "algorithms/grid/ray_cast.hpp"

#include <cmath>
#include <numbers>

namespace playerkit::emulators::p2os {

SonarArray::SonarArray(const hardware::p2os::RobotParams& params)
    : poses_(params.sonar_poses.begin(), params.sonar_poses.end()) {
  if (!poses_.empty() || params.sonar_count <= 0) return;
  const double radius = 0.8 * params.radius;
  for (int i = 0; i < params.sonar_count; ++i) {
    const double degrees = 90.0 - 360.0 * i / params.sonar_count;
    const double heading = geometry::normalize_angle(degrees * std::numbers::pi / 180.0);
    poses_.push_back({static_cast<int>(std::lround(radius * std::cos(heading))),
                      static_cast<int>(std::lround(radius * std::sin(heading))),
                      static_cast<int>(std::lround(heading * 180.0 / std::numbers::pi))});
  }
}

geometry::Pose2 SonarArray::world_pose(int index, const geometry::Pose2& robot) const {
  const hardware::p2os::SonarPose& pose = poses_.at(static_cast<std::size_t>(index));
  return robot.compose({pose.x / 1000.0, pose.y / 1000.0, pose.heading * std::numbers::pi / 180.0});
}

double SonarArray::range(int index, const grid::OccupancyGrid* map, const geometry::Pose2& robot,
                         double max_range) const {
  if (map == nullptr) return max_range;
  const geometry::Pose2 sensor = world_pose(index, robot);
  return grid::cast_ray(*map, sensor.translation(), sensor.yaw, max_range, grid::RayStop::occupied);
}

}  // namespace playerkit::emulators::p2os
