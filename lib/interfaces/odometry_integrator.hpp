#pragma once
// Odometry for any base, written once: wrapping encoder counters, the
// robot's own pose from them, and the reported pose that SET_ODOM and
// RESET_ODOM move without touching the hardware.
//
// Lengths are in whatever unit the caller scales its counts to (p2os keeps
// millimetres, the simulator metres); angles are radians, yaw in (-pi, pi].

#include <cstdint>
#include <optional>

#include "algorithms/geometry/pose2.hpp"

namespace playerkit::interfaces {

// The shortest signed difference between two readings of a `bits`-bit
// counter (1..31; bits above are ignored): a wrap is a step, not a jump.
[[nodiscard]] int wrapped_counter_step(std::uint32_t now, std::uint32_t before, int bits);

// A `bits`-bit reading as a signed distance from zero: the upper half of the
// range counts backwards from the wrap.
[[nodiscard]] int signed_counter_value(std::uint32_t value, int bits);

// One encoder counter followed across its wraps.
class WrappingCounter {
 public:
  explicit WrappingCounter(int bits) : bits_(bits) {}

  // The step since the previous reading; 0 for the first one.
  int update(std::uint32_t reading);
  // The next reading starts afresh (the counter was reset or reconnected).
  void forget() { last_.reset(); }

 private:
  int bits_;
  std::optional<std::uint32_t> last_;
};

// reported = correction ∘ robot: `robot` is the pose the base's counters
// give in their own frame, the correction is what requests and restarts of
// the counters put in front of it, so a client sees one continuous pose.
class OdometryIntegrator {
 public:
  // Counters that count x and y in the robot's odometric frame (P2OS XPOS/YPOS).
  void step_position(double dx, double dy);
  // A differential base: `distance` along the heading halfway through `turn`.
  void drive(double distance, double turn);
  // A heading the base reports whole (P2OS THPOS) rather than as steps.
  void set_heading(double yaw);

  // The counters give `robot` now; the correction stays.
  void set_robot_pose(const geometry::Pose2& robot) { robot_ = robot; }
  // The counters start again from `robot` (a reconnection): the reported
  // pose stays where it was.
  void restart_counters(const geometry::Pose2& robot);
  // The counters went back to zero where the reported pose last stood (a
  // hardware odometry reset obeyed) and read `robot` now.
  void counters_zeroed(const geometry::Pose2& robot);

  // SET_ODOM: the reported pose becomes `pose` now.
  void set_reported(const geometry::Pose2& pose);
  // RESET_ODOM: the reported pose becomes (0, 0, 0) now.
  void reset_reported() { set_reported({}); }
  void set_correction(const geometry::Pose2& correction) { correction_ = correction; }

  [[nodiscard]] geometry::Pose2 reported() const { return correction_.compose(robot_); }
  [[nodiscard]] const geometry::Pose2& robot() const { return robot_; }
  [[nodiscard]] const geometry::Pose2& correction() const { return correction_; }

 private:
  geometry::Pose2 robot_;
  geometry::Pose2 correction_;
};

}  // namespace playerkit::interfaces
