#include "algorithms/vfh/vfh_planner.hpp"

#include "algorithms/vfh/angles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace playerkit::vfh {

namespace {

// 1.5's trajectory circles: one turning radius for every speed.
constexpr double kTurningRadius = 0.15;  // m
// Openings narrower than this are ignored; wider than kWideOpening get
// candidates kOpeningMargin inside each edge as well as the middle.
constexpr double kNarrowestOpening = 10;  // degrees
constexpr double kWideOpening = 80;       // degrees
constexpr double kOpeningMargin = 40;     // degrees
// 1.5 steered proportionally over 75 degrees either side of ahead.
constexpr double kProportionalSpan = 75;  // degrees
// A goal nearer than this, in a direction no more than kPlainViewAngle off
// ahead (the laser sees the whole strip to it), is driven at straight when
// the strip the robot sweeps to it is clear.
constexpr double kPlainViewRange = 1.0;  // m
constexpr double kPlainViewAngle = 60;   // degrees

double radians(double degrees) { return degrees / kDegreesPerRadian; }

}  // namespace

VfhPlanner::VfhPlanner(const VfhParameters& parameters) : window_(parameters) { reset(); }

void VfhPlanner::reset() {
  binary_.assign(static_cast<std::size_t>(window_.sectors()), true);
  previous_direction_ = 90;
  speed_ = 0;
  escape_turn_ = 0;
}

std::vector<bool> VfhPlanner::free_sectors(const HistogramWindow::Reading& reading) {
  const VfhParameters& p = window_.parameters();
  for (std::size_t k = 0; k < binary_.size(); ++k) {
    if (reading.histogram[k] > p.obstacle_cutoff) binary_[k] = true;
    else if (reading.histogram[k] < p.free_space_cutoff) binary_[k] = false;
  }
  // The mask: obstacles within reach of the circles the robot turns on
  // close off every direction beyond them on that side.
  const double reach = kTurningRadius + p.robot_radius + p.safety_distance;
  const double centre_offset = kTurningRadius / p.cell_size;
  double right_limit = 0;
  double left_limit = 180;
  for (const int cell : reading.occupied) {
    const double direction = window_.direction(cell);
    if (direction < 90) {
      if (direction >= right_limit && window_.distance_to(cell, centre_offset, 0) < reach) right_limit = direction;
    } else if (direction < left_limit && window_.distance_to(cell, -centre_offset, 0) < reach) {
      left_limit = direction;
    }
  }
  std::vector<bool> free(binary_.size());
  for (std::size_t k = 0; k < free.size(); ++k) {
    const double start = static_cast<double>(k) * p.sector_angle;
    free[k] = !binary_[k] && start >= right_limit && start <= left_limit;
  }
  return free;
}

std::vector<double> VfhPlanner::candidates(const std::vector<bool>& free, double desired) const {
  const int sectors = static_cast<int>(free.size());
  const double width = window_.parameters().sector_angle;
  const auto first_blocked = std::find(free.begin(), free.end(), false);
  if (first_blocked == free.end()) return {desired};
  std::vector<double> found;
  const int from = static_cast<int>(first_blocked - free.begin());
  double opening_start = 0;
  bool in_opening = false;
  for (int step = 1; step <= sectors; ++step) {
    const int k = (from + step) % sectors;
    const int before = (k + sectors - 1) % sectors;
    if (free[static_cast<std::size_t>(k)] && !in_opening) {
      in_opening = true;
      opening_start = k * width;
    } else if (!free[static_cast<std::size_t>(k)] && in_opening) {
      in_opening = false;
      const double opening_end = before * width;  // the start of its last free sector
      const double span = opening_end - opening_start;
      if (span < kNarrowestOpening) continue;
      found.push_back(wrap_degrees((opening_start + opening_end) / 2));
      if (span < kWideOpening) continue;
      const double right_edge = wrap_degrees(opening_start + kOpeningMargin);
      const double left_edge = wrap_degrees(opening_end - kOpeningMargin);
      found.push_back(right_edge);
      found.push_back(left_edge);
      if (opening_start + kOpeningMargin < desired && desired < opening_end - kOpeningMargin) found.push_back(desired);
    }
  }
  return found;
}

double VfhPlanner::turn_rate_towards(double direction) const {
  const double max_turn = window_.parameters().max_turn_rate;
  if (direction > 270 && direction < 360) return -max_turn;
  if (direction > 180 && direction <= 270) return max_turn;
  const double rate = std::round((direction - 90) / kProportionalSpan * (max_turn * kDegreesPerRadian));
  return std::clamp(radians(rate), -max_turn, max_turn);
}

bool VfhPlanner::in_plain_view(const RangeTable& ranges, double desired, double goal_distance) const {
  const VfhParameters& p = window_.parameters();
  if (!(goal_distance <= kPlainViewRange) || angle_between(desired, 90) > kPlainViewAngle) return false;
  // Up to where the robot's front would stand at the goal.
  return ranges.strip_clear(desired, goal_distance + p.robot_radius, p.robot_radius + p.safety_distance);
}

Steering VfhPlanner::step(const Scan& scan, double desired, double dt, double speed_limit, double goal_distance) {
  const VfhParameters& p = window_.parameters();
  const RangeTable ranges(scan);
  const std::vector<bool> free = free_sectors(window_.read(ranges));
  Steering steering;
  steering.candidates = candidates(free, wrap_degrees(desired));
  if (in_plain_view(ranges, wrap_degrees(desired), goal_distance)) steering.candidates = {wrap_degrees(desired)};

  double best_cost = 0;
  for (const double candidate : steering.candidates) {
    const double cost = p.weight_desired_direction * angle_between(desired, candidate) +
                        p.weight_current_direction * angle_between(previous_direction_, candidate);
    if (!steering.direction || cost < best_cost) {
      steering.direction = candidate;
      best_cost = cost;
    }
  }

  if (!steering.direction) {
    // No way forward: turn in place towards the roomier side, and keep to it
    // until a way opens, so the robot never rocks between two directions.
    if (escape_turn_ == 0) {
      escape_turn_ = ranges.nearest_around(135, 40) >= ranges.nearest_around(45, 40) ? 1 : -1;
    }
    speed_ = 0;
    steering.blocked = true;
    steering.turn_rate = escape_turn_ * p.max_turn_rate;
    return steering;
  }
  escape_turn_ = 0;
  previous_direction_ = *steering.direction;

  // Ramp up, but never faster than the room ahead allows.
  const double clearance = p.robot_radius + p.safety_distance;
  const double free_ahead = ranges.nearest_around(std::clamp(*steering.direction, 0.0, 180.0), 15) - clearance;
  const double room = std::clamp((free_ahead - p.stop_distance) / p.slow_down_distance, 0.0, 1.0);
  speed_ = std::min({speed_ + p.acceleration * dt, p.max_speed * room, std::max(speed_limit, 0.0)});
  steering.speed = speed_;
  steering.turn_rate = turn_rate_towards(*steering.direction);
  return steering;
}

}  // namespace playerkit::vfh
