#include "algorithms/vfh/vfh_navigator.hpp"

#include "algorithms/vfh/angles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>
#include <stdexcept>

namespace playerkit::vfh {

namespace {

// Getting this much nearer the goal counts as progress.
constexpr double kProgress = 0.25;  // m

}  // namespace

const char* phase_name(Phase phase) {
  switch (phase) {
    case Phase::idle: return "idle";
    case Phase::velocity: return "velocity";
    case Phase::backing_off: return "backing_off";
    case Phase::turning_first: return "turning_first";
    case Phase::steering: return "steering";
    case Phase::escaping: return "escaping";
    case Phase::aligning: return "aligning";
  }
  return "?";
}

VfhNavigator::VfhNavigator(const NavigatorSettings& settings) : settings_(settings), planner_(settings.planner) {
  if (!(settings.distance_epsilon > 0) || !(settings.angle_epsilon > 0)) {
    throw std::invalid_argument("vfh: distance_epsilon and angle_epsilon must be above 0");
  }
  if (!(settings.backoff_speed >= 0) || !(settings.backoff_time >= 0)) {
    throw std::invalid_argument("vfh: the stall back-off must not be negative");
  }
}

void VfhNavigator::go_to(const geometry::Pose2& goal) {
  if (goal_ && goal_->x == goal.x && goal_->y == goal.y && goal_->yaw == goal.yaw) return;
  // A global planner hands the same waypoint down again, a few centimetres
  // off, each time its localization corrects the odometric frame. Starting
  // over on each correction undid the turn to the goal's heading at every
  // one: just outside distance_epsilon again, the robot turned back to face
  // the point, and rocked there for half a minute and more.
  const bool refined = mode_ == Mode::goal && goal_ &&
                       std::hypot(goal.x - goal_->x, goal.y - goal_->y) < settings_.distance_epsilon;
  goal_ = goal;
  if (refined) return;
  mode_ = Mode::goal;
  planner_.reset();
  backing_off_ = 0;
  closest_ = std::numeric_limits<double>::infinity();
  turned_without_progress_ = 0;
  escaping_ = false;
  at_position_ = false;
  turning_first_ = false;
  steering_ = false;
}

void VfhNavigator::drive(double speed, double turn_rate) {
  mode_ = Mode::velocity;
  commanded_speed_ = speed;
  commanded_turn_ = turn_rate;
}

void VfhNavigator::stop() {
  mode_ = Mode::idle;
  backing_off_ = 0;
}

Motion VfhNavigator::step(const geometry::Pose2& pose, const Scan& scan, double dt, bool stalled) {
  switch (mode_) {
    case Mode::idle:
      phase_ = Phase::idle;
      return {};
    case Mode::velocity: {
      phase_ = Phase::velocity;
      // Forward only as fast as the room ahead allows; the laser sees
      // nothing behind, so reversing is the client's own responsibility.
      double speed = commanded_speed_;
      if (speed > 0) {
        const VfhParameters& p = settings_.planner;
        const double free_ahead = RangeTable(scan).nearest_around(90, 15) - p.robot_radius - p.safety_distance;
        speed *= std::clamp((free_ahead - p.stop_distance) / p.slow_down_distance, 0.0, 1.0);
      }
      return {.speed = speed, .turn_rate = commanded_turn_};
    }
    case Mode::goal:
      return towards_goal(pose, scan, dt, stalled);
  }
  return {};
}

Motion VfhNavigator::turn_in_place(double heading_error) const {
  // As 1.5: proportional over 180 degrees, whole degrees a second, at least
  // the minimum turn rate (slower does not move a real base).
  const VfhParameters& p = settings_.planner;
  if (std::abs(heading_error) <= settings_.angle_epsilon) return {};
  const double max_degrees = p.max_turn_rate * kDegreesPerRadian;
  double rate = std::round(heading_error * kDegreesPerRadian / 180.0 * max_degrees) / kDegreesPerRadian;
  if (std::abs(rate) < p.min_turn_rate) rate = std::copysign(p.min_turn_rate, heading_error);
  return {.speed = 0, .turn_rate = rate};
}

Motion VfhNavigator::towards_goal(const geometry::Pose2& pose, const Scan& scan, double dt, bool stalled) {
  const VfhParameters& p = settings_.planner;
  if (backing_off_ > 0) {
    phase_ = Phase::backing_off;
    backing_off_ -= dt;
    if (backing_off_ <= 0) planner_.reset();
    return {.speed = -settings_.backoff_speed, .turn_rate = 0};
  }
  if (stalled && planner_.speed() > 0) {
    // Pushing against something the laser missed (too low, too dark):
    // back off a little and look again.
    ++stalls_;
    phase_ = Phase::backing_off;
    backing_off_ = settings_.backoff_time;
    return {.speed = -settings_.backoff_speed, .turn_rate = 0};
  }
  const double dx = goal_->x - pose.x;
  const double dy = goal_->y - pose.y;
  const double distance = std::hypot(dx, dy);
  const double heading_error = geometry::angle_difference(goal_->yaw, pose.yaw);
  // Once there, turning to the goal's heading goes on even if it carries
  // the robot a little beyond distance_epsilon (a laser or a caster off the
  // turning centre): switching back to driving at the point, now behind it,
  // would rock between the two turns.
  if (distance < settings_.distance_epsilon) {
    at_position_ = true;
  } else if (distance > 2.0 * settings_.distance_epsilon) {
    at_position_ = false;
  }
  if (at_position_) {
    phase_ = Phase::aligning;
    if (std::abs(heading_error) < settings_.angle_epsilon) {
      mode_ = Mode::idle;
      return {.reached = true};
    }
    return turn_in_place(heading_error);
  }
  if (distance < closest_ - kProgress) {
    closest_ = distance;
    turned_without_progress_ = 0;
  }
  // A goal well off to the side or behind: turn towards it on the spot
  // first (1.5's wavefront inserted rotation waypoints for this); driving
  // on, the robot would circle it or sweep wide past it. Not while escaping
  // a dead end, which would turn it straight back in.
  // With hysteresis: once turned to within half of turn_first_angle the
  // planner steers, and may lead it up to 1.5 times that angle away (round
  // an obstacle) before the robot turns on the spot again. One threshold
  // rocked it: the turn brought the goal just inside it, the planner's way
  // round took it just outside, ten times a second.
  const double bearing_error = geometry::angle_difference(std::atan2(dy, dx), pose.yaw);
  const double turn_first_above = steering_ ? 1.5 * settings_.turn_first_angle : settings_.turn_first_angle;
  if (!escaping_ && std::abs(bearing_error) > turn_first_above) turning_first_ = true;
  if (turning_first_ && std::abs(bearing_error) < settings_.turn_first_angle / 2) turning_first_ = false;
  Motion motion;
  if (turning_first_) {
    planner_.reset();
    steering_ = false;
    phase_ = Phase::turning_first;
    motion = turn_in_place(bearing_error);
  } else {
    steering_ = true;
    const double desired = wrap_degrees(90.0 + bearing_error * kDegreesPerRadian);
    // Arrive without circling: no faster than stops in the distance left, and
    // than turns on a circle of half of it (1.5 circled goals it never slowed for).
    const double limit = std::min(std::sqrt(2.0 * p.acceleration * distance), p.max_turn_rate * distance / 2.0);
    const Steering steering = planner_.step(scan, desired, dt, limit, distance);
    escaping_ = steering.blocked;
    phase_ = escaping_ ? Phase::escaping : Phase::steering;
    motion = {.speed = steering.speed, .turn_rate = steering.turn_rate};
  }
  // Turning round and round without getting nearer: spinning in a dead end,
  // or rocking between two ways round. Give up and say so.
  turned_without_progress_ += std::abs(motion.turn_rate) * dt;
  if (turned_without_progress_ >= settings_.stuck_turn) {
    ++stuck_events_;
    mode_ = Mode::idle;
    return {.stuck = true};
  }
  return motion;
}

}  // namespace playerkit::vfh
