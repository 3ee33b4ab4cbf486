// The devices' requests (reb.md §3.5) through lib/interfaces, which checks
// each payload's size once and NACKs the rest (1.5 NACKed a wrong size and
// then did the request anyway, or did not answer at all).
#include <cmath>
#include <numbers>

#include "families/reb/driver/reb_connection.hpp"
#include "links/link_error.hpp"

namespace playerkit::drivers::reb {

namespace hw = hardware::reb;

core::RequestResult RebConnection::handle_request(RebRole role, const core::Request& request) {
  switch (role) {
    case RebRole::position: return interfaces::answer_position_request(*this, request);
    case RebRole::ir: return interfaces::answer_ir_request(*this, request);
    case RebRole::power: return core::RequestResult::nack();  // 1.5 answered none
  }
  return core::RequestResult::nack();
}

template <class Work>
bool RebConnection::with_board(Work work) {
  if (!session_up_ || lost_ || !exchanger_) return false;
  try {
    work();
    return true;
  } catch (const links::ExchangeError& e) {
    lost_ = e.what();
  } catch (const links::LinkError& e) {
    lost_ = e.what();
  }
  return false;
}

std::optional<interfaces::BaseGeometry> RebConnection::geometry() {
  // The UBot as 1.5 described it: a 180 mm square centred on the axle.
  const double size = 2.0 * params_.robot_radius_mm / 1000.0;
  return interfaces::BaseGeometry{.pose = {}, .length = size, .width = size};
}

bool RebConnection::set_motor_power(bool on) {
  motors_enabled_ = on;
  if (!position_started_) return true;
  return with_board([&] {
    if (mode_ == ControlMode::position) {
      if (!on) exchange_both(hw::set_speed, 0, 0);  // a move under way stops
    } else {
      send_motor_speeds(false);
    }
  });
}

bool RebConnection::set_velocity_mode(std::uint8_t mode) {
  const bool was_position = mode_ == ControlMode::position;
  mode_ = mode == 0 ? ControlMode::direct_velocity : ControlMode::heading;
  if (!position_started_) return true;
  return with_board([&] { send_motor_speeds(was_position); });
}

bool RebConnection::set_position_mode(bool position_control) {
  if (!position_control) return set_velocity_mode(mode_ == ControlMode::heading ? 1 : 0);
  mode_ = ControlMode::position;
  command_ = {};  // the next xspeed or yawspeed is a move
  on_target_ = true;
  if (!position_started_) return true;
  // Velocity set-points are no move: the robot waits for one.
  return with_board([&] {
    exchange_both(hw::set_speed, 0, 0);
    speeds_sent_ = hw::MotorSpeeds{};
  });
}

bool RebConnection::reset_odometry() { return set_odometry({}); }

bool RebConnection::set_odometry(const geometry::Pose2& pose) {
  return with_board([&] {
    if (position_started_) zero_counters();
    odometry_.set_reported(pose);
  });
}

bool RebConnection::set_speed_pid(const interfaces::PidGains& gains) {
  return with_board([&] {
    exchange(hw::speed_pid(hw::Motor::left, gains.kp, gains.ki, gains.kd));
    exchange(hw::speed_pid(hw::Motor::right, gains.kp, gains.ki, gains.kd));
  });
}

bool RebConnection::set_position_pid(const interfaces::PidGains& gains) {
  return with_board([&] {
    exchange(hw::position_pid(hw::Motor::left, gains.kp, gains.ki, gains.kd));
    exchange(hw::position_pid(hw::Motor::right, gains.kp, gains.ki, gains.kd));
  });
}

bool RebConnection::set_speed_profile(const interfaces::SpeedProfile& profile) {
  // mm/s and mm/s² in pulses per 10 ms (and per 10 ms²), as 1.5 converted
  // them; the board takes an acceleration of at most 100.
  const std::int32_t speed = hw::pulses_per_10ms(profile.speed, params_);
  std::int32_t acceleration = std::min(hw::pulses_per_10ms(profile.acceleration, params_), 100);
  if (acceleration <= 0) acceleration = 10;
  if (speed <= 0) return false;
  return with_board([&] {
    exchange(hw::speed_profile(hw::Motor::left, speed, acceleration));
    exchange(hw::speed_profile(hw::Motor::right, speed, acceleration));
  });
}

std::optional<std::vector<geometry::Pose2>> RebConnection::sensor_poses() {
  std::vector<geometry::Pose2> poses;
  for (const auto& [x, y, heading] : params_.ir_poses) {
    poses.push_back({x / 1000.0, y / 1000.0, geometry::normalize_angle(heading * std::numbers::pi / 180.0)});
  }
  return poses;
}

bool RebConnection::set_power(bool on) {
  return with_board([&] {
    exchange(hw::ir_power(on));
    ir_sent_ = on;
  });
}

}  // namespace playerkit::drivers::reb
