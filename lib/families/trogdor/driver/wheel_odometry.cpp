#include "families/trogdor/driver/wheel_odometry.hpp"

#include <cmath>
#include <algorithm>
#include <cstdlib>

#include "families/trogdor/protocol/trogdor_units.hpp"

namespace playerkit::drivers::trogdor {

namespace hw = hardware::trogdor;

namespace {

// Slack on the time between readings: the host's clock sees the reply, not
// the moment the robot latched its counters.
constexpr double kTimingSlack = 0.05;  // s

std::int64_t counter_step(std::int32_t now, std::int32_t before) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(now) - static_cast<std::uint32_t>(before));
}

}  // namespace

bool WheelOdometry::update(const hw::OdometryReading& reading, double elapsed) {
  const hw::BodyVelocity speeds = hw::body_velocity(reading.left_velocity, reading.right_velocity);
  velocity_ = {speeds.forward, 0.0, speeds.turn_rate};
  if (!last_) {
    last_ = reading;
    return true;
  }
  const std::int64_t left = counter_step(reading.left_count, last_->left_count);
  const std::int64_t right = counter_step(reading.right_count, last_->right_count);
  last_ = reading;
  const double tick = hw::metres_per_tick();
  const double farthest = hw::kMaxWheelSpeed * (std::max(elapsed, 0.0) + kTimingSlack);
  if (static_cast<double>(std::max(std::llabs(left), std::llabs(right))) * tick > farthest) {
    ++skipped_;
    return false;
  }
  const double left_distance = static_cast<double>(left) * tick;
  const double right_distance = static_cast<double>(right) * tick;
  integrator_.drive((left_distance + right_distance) / 2, (right_distance - left_distance) / hw::kAxleLength);
  return true;
}

}  // namespace playerkit::drivers::trogdor
