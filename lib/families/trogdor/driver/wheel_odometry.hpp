#pragma once
// The robot's pose from its two wheel counters (trogdor.md §3 "Odometry"),
// without the reference's hacks: a count of 0 is a count like any other,
// counters wrap as the int32s they are, and a reading no wheel could
// produce (faster than 5 m/s since the last) is skipped and the counters
// followed from it, instead of being compared with a stale reading forever.

#include <cstdint>
#include <optional>

#include "algorithms/geometry/pose2.hpp"
#include "families/trogdor/protocol/trogdor_messages.hpp"
#include "interfaces/odometry_integrator.hpp"

namespace playerkit::drivers::trogdor {

class WheelOdometry {
 public:
  // `elapsed` seconds since the previous reading. False when the reading
  // was skipped as impossible (the first one after start() only sets the
  // counters' origin and is true).
  bool update(const hardware::trogdor::OdometryReading& reading, double elapsed);
  // The next reading sets the counters' origin again (the robot was
  // reconnected: its counters may have been restarted); the pose stays.
  void restart() { last_.reset(); }

  // What a client sees: the integrated pose behind RESET_ODOM and SET_ODOM.
  interfaces::OdometryIntegrator& pose() { return integrator_; }
  [[nodiscard]] geometry::Pose2 reported() const { return integrator_.reported(); }
  // Forward m/s and rad/s (x and yaw) from the wheel velocities last reported.
  [[nodiscard]] const geometry::Pose2& velocity() const { return velocity_; }
  [[nodiscard]] std::uint64_t skipped() const { return skipped_; }

 private:
  interfaces::OdometryIntegrator integrator_;
  std::optional<hardware::trogdor::OdometryReading> last_;
  geometry::Pose2 velocity_;
  std::uint64_t skipped_ = 0;
};

}  // namespace playerkit::drivers::trogdor
