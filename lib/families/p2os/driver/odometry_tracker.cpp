#include "families/p2os/driver/odometry_tracker.hpp"

#include <cmath>

namespace playerkit::drivers::p2os {

namespace {

// A 12-bit counter reading as a signed distance from zero.
int signed_counter(std::uint16_t value) {
  return interfaces::signed_counter_value(value, kPositionCounterBits);
}

// THPOS as a signed number of units from zero, within one turn.
int signed_heading(int units, int per_turn) {
  int v = units % per_turn;
  if (v < 0) v += per_turn;
  return v >= per_turn / 2 ? v - per_turn : v;
}

// How a heading difference weighs against a distance when telling the
// robot's reset from ordinary motion: the arc at a Pioneer's radius.
constexpr double kHeadingWeightMm = 250.0;

}  // namespace

OdometryTracker::OdometryTracker(const hardware::p2os::RobotParams& params) : params_(&params) {}

void OdometryTracker::start_session(const hardware::p2os::RobotParams& params) {
  params_ = &params;
  session_started_ = false;
  reset_window_ = 0;
}

double OdometryTracker::heading_radians(std::int16_t heading) const {
  return geometry::normalize_angle(heading * params_->angle_conv_factor);
}

bool OdometryTracker::looks_reset(const Raw& raw) const {
  const int per_turn = params_->heading_units_per_turn();
  const double distance = params_->dist_conv_factor;
  const double turn = params_->angle_conv_factor * kHeadingWeightMm;
  const double from_last =
      std::hypot(wrapped_step(raw.x, last_.x), wrapped_step(raw.y, last_.y)) * distance +
      std::abs(signed_heading(raw.heading - last_.heading, per_turn)) * turn;
  const double from_zero = std::hypot(signed_counter(raw.x), signed_counter(raw.y)) * distance +
                           std::abs(signed_heading(raw.heading, per_turn)) * turn;
  return from_zero < from_last;
}

void OdometryTracker::update(std::uint16_t x_position, std::uint16_t y_position, std::int16_t heading) {
  const Raw raw{static_cast<std::uint16_t>(x_position & 0x0FFF),
                static_cast<std::uint16_t>(y_position & 0x0FFF), heading};
  const double distance = params_->dist_conv_factor;
  // The robot's pose counted from its counters' zero (where OPEN or SETO left them).
  const geometry::Pose2 from_zero{signed_counter(raw.x) * distance, signed_counter(raw.y) * distance,
                                  heading_radians(raw.heading)};

  if (!session_started_) {
    if (counters_are_pose_) {
      // SETO went out before this SIP: the counters count from where the
      // robot obeyed it, which is the origin. (Had this SIP left the robot
      // before it obeyed, the jump still to come is absorbed below.)
      odometry_.set_robot_pose(from_zero);
      odometry_.set_correction({});
    } else if (start_pose_) {
      odometry_.set_robot_pose(from_zero);
      odometry_.set_reported(*start_pose_);
    } else if (first_session_) {
      // As 1.5: x = y = 0 at the first SIP, the heading is the robot's.
      odometry_.set_robot_pose(from_zero);
      odometry_.set_correction({-from_zero.x, -from_zero.y, 0.0});
    } else {
      odometry_.restart_counters(from_zero);
    }
    start_pose_.reset();
    counters_are_pose_ = false;
    first_session_ = false;
    session_started_ = true;
    have_reading_ = true;
    last_ = raw;
    return;
  }

  if (reset_window_ > 0) {
    --reset_window_;
    if (looks_reset(raw)) {
      // The new origin is where the robot stood when it obeyed SETO, which
      // is (within one SIP) where it was last reported.
      odometry_.counters_zeroed(from_zero);
      reset_window_ = 0;
      last_ = raw;
      return;
    }
  }

  odometry_.step_position(wrapped_step(raw.x, last_.x) * distance, wrapped_step(raw.y, last_.y) * distance);
  odometry_.set_heading(from_zero.yaw);
  last_ = raw;
}

void OdometryTracker::robot_reset_sent() {
  reset_window_ = kResetWindow;
  if (have_reading_ && session_started_) {
    odometry_.reset_reported();
  } else {
    counters_are_pose_ = true;
    start_pose_.reset();
  }
}

void OdometryTracker::set_pose(const geometry::Pose2& pose) {
  if (have_reading_ && session_started_) {
    odometry_.set_reported(pose);
  } else {
    // Between sessions: the next session starts from it.
    start_pose_ = pose;
    counters_are_pose_ = false;
  }
}

geometry::Pose2 OdometryTracker::pose() const { return odometry_.reported(); }

}  // namespace playerkit::drivers::p2os
