#include "families/segwayrmp/protocol/rmp_odometry.hpp"

#include <cmath>
#include <numbers>

#include "families/segwayrmp/protocol/rmp_frames.hpp"

namespace playerkit::hardware::segwayrmp {

std::int64_t counter_change(std::uint32_t from, std::uint32_t to) {
  return static_cast<std::int32_t>(to - from);
}

const OdometryPose& RmpOdometry::update(std::uint32_t fore_aft, std::uint32_t yaw) {
  if (last_) {
    const double distance = static_cast<double>(counter_change(last_->fore_aft, fore_aft)) / kForeAftCountsPerMetre;
    const double turn =
        static_cast<double>(counter_change(last_->yaw, yaw)) / kYawCountsPerRevolution * 2 * std::numbers::pi;
    pose_.x += distance * std::cos(pose_.theta);
    pose_.y += distance * std::sin(pose_.theta);
    pose_.theta = std::fmod(pose_.theta + turn, 2 * std::numbers::pi);
    if (pose_.theta < 0) pose_.theta += 2 * std::numbers::pi;
  }
  last_ = Counters{fore_aft, yaw};
  return pose_;
}

void RmpOdometry::reset() {
  pose_ = {};
  last_.reset();
}

}  // namespace playerkit::hardware::segwayrmp
