#include "families/p2os/emulator/sonar_array.hpp"

#include <cmath>
#include <numbers>

namespace playerkit::emulators::p2os {

namespace {

mobile_base::RangeRing ring_of(const std::vector<hardware::p2os::SonarPose>& poses) {
  std::vector<geometry::Pose2> metric;
  for (const auto& pose : poses) {
    metric.push_back({pose.x / 1000.0, pose.y / 1000.0, pose.heading * std::numbers::pi / 180.0});
  }
  return mobile_base::RangeRing(std::move(metric));
}

}  // namespace

SonarArray::SonarArray(const hardware::p2os::RobotParams& params)
    : poses_(params.sonar_poses.begin(), params.sonar_poses.end()) {
  if (poses_.empty() && params.sonar_count > 0) {
    // Whole millimetres and degrees, as the row would give them.
    for (const geometry::Pose2& pose :
         mobile_base::evenly_spaced_ring(params.sonar_count, 0.8 * params.radius, std::numbers::pi / 2,
                                         mobile_base::RingOrder::clockwise)) {
      poses_.push_back({static_cast<int>(std::lround(pose.x)), static_cast<int>(std::lround(pose.y)),
                        static_cast<int>(std::lround(pose.yaw * 180.0 / std::numbers::pi))});
    }
  }
  ring_ = ring_of(poses_);
}

}  // namespace playerkit::emulators::p2os
