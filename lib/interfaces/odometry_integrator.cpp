#include "interfaces/odometry_integrator.hpp"

#include <cmath>

namespace playerkit::interfaces {

namespace {

std::int64_t counter_span(int bits) { return std::int64_t{1} << bits; }

std::int64_t counter_bits_of(std::uint32_t value, int bits) {
  return static_cast<std::int64_t>(value) & (counter_span(bits) - 1);
}

}  // namespace

int wrapped_counter_step(std::uint32_t now, std::uint32_t before, int bits) {
  const std::int64_t span = counter_span(bits);
  std::int64_t step = counter_bits_of(now, bits) - counter_bits_of(before, bits);
  if (step >= span / 2) step -= span;
  if (step < -span / 2) step += span;
  return static_cast<int>(step);
}

int signed_counter_value(std::uint32_t value, int bits) {
  const std::int64_t span = counter_span(bits);
  const std::int64_t v = counter_bits_of(value, bits);
  return static_cast<int>(v >= span / 2 ? v - span : v);
}

int WrappingCounter::update(std::uint32_t reading) {
  const int step = last_ ? wrapped_counter_step(reading, *last_, bits_) : 0;
  last_ = reading;
  return step;
}

void OdometryIntegrator::step_position(double dx, double dy) {
  robot_.x += dx;
  robot_.y += dy;
}

void OdometryIntegrator::drive(double distance, double turn) {
  // The chord of the arc points halfway through the turn.
  const double along = robot_.yaw + turn / 2.0;
  robot_.x += distance * std::cos(along);
  robot_.y += distance * std::sin(along);
  robot_.yaw = geometry::normalize_angle(robot_.yaw + turn);
}

void OdometryIntegrator::set_heading(double yaw) { robot_.yaw = geometry::normalize_angle(yaw); }

void OdometryIntegrator::restart_counters(const geometry::Pose2& robot) {
  const geometry::Pose2 before = reported();
  robot_ = robot;
  set_reported(before);
}

void OdometryIntegrator::counters_zeroed(const geometry::Pose2& robot) {
  correction_ = reported();
  robot_ = robot;
}

void OdometryIntegrator::set_reported(const geometry::Pose2& pose) { correction_ = pose.compose(robot_.inverse()); }

}  // namespace playerkit::interfaces
