#pragma once
// What the vfh driver does with its client's commands (vfh.md §1, §2.1), as
// pure logic: a goal in the odometric frame (position mode) reached through
// the VfhPlanner; speeds passed through with the forward speed capped by the
// room ahead (velocity mode; 1.5 passed them only while a goal was active,
// and blindly); a stall escape; and "stuck", said once, when no way opens
// for a turn and a half without getting nearer, so that a global planner can
// plan again. A goal more than 60 degrees off is turned to on the spot first.

#include <cstdint>
#include <numbers>
#include <optional>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/vfh/vfh_planner.hpp"

namespace playerkit::vfh {

struct NavigatorSettings {
  VfhParameters planner;
  double distance_epsilon = 0.5;     // m: near enough to the goal
  double angle_epsilon = 10 * std::numbers::pi / 180;  // rad: facing it closely enough
  double turn_first_angle = 60 * std::numbers::pi / 180;  // rad: a goal further off is turned to on the spot
  double stuck_turn = 3 * std::numbers::pi;  // rad turned without getting 0.25 m nearer: stuck
  double backoff_speed = 0.1;        // m/s, backwards, after a stall
  double backoff_time = 1.0;         // s
};

// What the navigator did in its last step (for traces and tests).
enum class Phase { idle, velocity, backing_off, turning_first, steering, escaping, aligning };
const char* phase_name(Phase phase);

struct Motion {
  double speed = 0;      // m/s
  double turn_rate = 0;  // rad/s
  bool reached = false;  // the goal was reached in this step
  bool stuck = false;    // the goal was given up in this step: turning without getting nearer
};

class VfhNavigator {
 public:
  // Throws std::invalid_argument for bad settings.
  explicit VfhNavigator(const NavigatorSettings& settings);

  // Position mode. The same goal again is not a new goal (as in 1.5): a
  // client re-sending its command every cycle does not restart anything.
  // Nor does a goal within distance_epsilon of the active one: that is the
  // same goal, corrected; the robot carries on towards it as it was.
  void go_to(const geometry::Pose2& goal);
  // Velocity mode: forward speed, turn rate.
  void drive(double speed, double turn_rate);
  // Motors off: nothing moves until the next command.
  void stop();

  // One cycle, on new odometry: `pose` in the odometric frame, the latest
  // scan, the seconds since the last cycle, whether the base says it stalled.
  Motion step(const geometry::Pose2& pose, const Scan& scan, double dt, bool stalled);

  [[nodiscard]] bool goal_active() const { return mode_ == Mode::goal; }
  [[nodiscard]] std::optional<geometry::Pose2> goal() const { return goal_; }
  [[nodiscard]] Phase phase() const { return phase_; }
  [[nodiscard]] std::uint64_t stuck_events() const { return stuck_events_; }
  [[nodiscard]] std::uint64_t stalls() const { return stalls_; }

 private:
  enum class Mode { idle, goal, velocity };
  Motion towards_goal(const geometry::Pose2& pose, const Scan& scan, double dt, bool stalled);
  Motion turn_in_place(double heading_error) const;

  NavigatorSettings settings_;
  VfhPlanner planner_;
  Mode mode_ = Mode::idle;
  Phase phase_ = Phase::idle;
  std::optional<geometry::Pose2> goal_;  // the last goal given, reached or not
  double commanded_speed_ = 0;
  double commanded_turn_ = 0;
  double backing_off_ = 0;               // s of backing off left
  double closest_ = 0;                   // m: the nearest to the goal so far
  double turned_without_progress_ = 0;   // rad turned since it last got nearer
  bool escaping_ = false;                // the planner found no way at the last step
  bool at_position_ = false;             // within distance_epsilon: turning to the goal's heading
  bool turning_first_ = false;           // turning on the spot towards a goal well off to the side
  bool steering_ = false;                // the planner steers (since the last turn on the spot)
  std::uint64_t stuck_events_ = 0;
  std::uint64_t stalls_ = 0;
};

}  // namespace playerkit::vfh
