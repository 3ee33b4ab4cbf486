// The I/O thread's cycle: subscription edges, commands, the poll of the
// board and publishing (reb.md §2 "Sequences", §3.2-3.4).
#include <algorithm>
#include <cmath>
#include <utility>
#include <numbers>

#include "families/reb/driver/reb_connection.hpp"
#include "interfaces/position_data.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/errors.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/power.hpp"

namespace playerkit::drivers::reb {

namespace hw = hardware::reb;
using namespace std::chrono_literals;

namespace {

// The board answers a command in 2 to 3 ms: a cycle of up to six exchanges
// fits in 25 ms, 40 readings a second.
constexpr auto kCyclePeriod = 25ms;

// The speed profile for position moves at start-up: 1 mm per 10 ms (reb.md §2).
std::int32_t start_profile(const hw::RebParams& params) {
  const std::int32_t value = static_cast<std::int32_t>(std::lround(100.0 * params.pulses_per_mm * 0.01));
  return std::clamp(value == 0 ? 10 : value, 1, 100);
}

}  // namespace

bool RebConnection::has(RebRole role) const {
  return std::any_of(views_.begin(), views_.end(), [role](const View& view) { return view.role == role; });
}

void RebConnection::reconcile_subscriptions() {
  const bool position = has(RebRole::position);
  if (position && !position_started_) start_position();
  if (!position && position_started_) {
    // The last position subscriber left: stop, as 1.5 did.
    exchange_both(hw::set_speed, 0, 0);
    speeds_sent_ = hw::MotorSpeeds{};
    position_started_ = false;
    position_resumed_ = false;
    motors_enabled_ = false;
  }
  const bool ir = has(RebRole::ir);
  // The emitters follow the subscription's edges; IR POWER in between is the client's.
  if (ir != ir_attached_) {
    exchange(hw::ir_power(ir));
    ir_sent_ = ir;
    ir_attached_ = ir;
    if (!ir) ir_readings_.clear();
  }
}

void RebConnection::start_position() {
  exchange_both(hw::set_speed, 0, 0);
  speeds_sent_ = hw::MotorSpeeds{};
  // Back after a gap: what the wheels did meanwhile counts, unless the board
  // was reset (read_odometry() refuses a step no wheel could make).
  if (position_resumed_) read_odometry();
  zero_counters();
  exchange(hw::speed_pid(hw::Motor::right, 1000, 0, 10));
  exchange(hw::speed_pid(hw::Motor::left, 1000, 0, 10));
  exchange(hw::position_pid(hw::Motor::right, params_.position_kp, 0, 10));
  exchange(hw::position_pid(hw::Motor::left, params_.position_kp, 0, 10));
  const std::int32_t profile = start_profile(params_);
  exchange(hw::speed_profile(hw::Motor::right, profile, profile));
  exchange(hw::speed_profile(hw::Motor::left, profile, profile));
  position_started_ = true;
  if (std::exchange(position_resumed_, false)) return;
  // A new subscriber: motors off, odometry at (0, 0, 0), the option's mode, as 1.5.
  motors_enabled_ = false;
  command_ = {};
  odometry_ = {};
  velocity_ = {};
  mode_ = heading_default_ ? ControlMode::heading : ControlMode::direct_velocity;
}

void RebConnection::zero_counters() {
  exchange(hw::set_position(hw::Motor::left, 0));
  exchange(hw::set_position(hw::Motor::right, 0));
  const Clock::time_point now = Clock::now();
  left_counter_ = CounterReading{0, now};
  right_counter_ = CounterReading{0, now};
  right_lag_ = 0.0;
}

void RebConnection::serve_requests() {
  for (const View& view : views_) {
    if (view.device->pending_requests() > 0) view.device->service_requests();
  }
}

void RebConnection::take_commands() {
  for (const View& view : views_) {
    if (view.role != RebRole::position) continue;
    const auto command = view.device->take_command();
    if (!command) continue;
    protocol::PositionCommand decoded;
    try {
      decoded = protocol::decode<protocol::PositionCommand>(command->payload);
    } catch (const protocol::DecodeError&) {
      continue;  // the device checked the size; nothing else can be wrong
    }
    const protocol::PositionCommand previous = std::exchange(command_, decoded);
    if (mode_ != ControlMode::position) {
      send_motor_speeds(false);
      continue;
    }
    // Position mode (reb.md §3.2): a new xspeed is a move of that many mm,
    // else a new yawspeed a turn of that many degrees; only with the motors on.
    if (!motors_enabled_) continue;
    std::int32_t left = 0;
    std::int32_t right = 0;
    if (decoded.xspeed != previous.xspeed) {
      left = hw::move_pulses(decoded.xspeed, params_);
      right = -left;
    } else if (decoded.yawspeed != previous.yawspeed) {
      left = hw::turn_pulses(decoded.yawspeed, params_);
      right = left;
    } else {
      continue;
    }
    // The odometry takes what was driven before the counters restart.
    read_odometry();
    zero_counters();
    exchange(hw::move_to(hw::Motor::left, left));
    exchange(hw::move_to(hw::Motor::right, right));
    on_target_ = false;
  }
}

void RebConnection::send_motor_speeds(bool even_if_unchanged) {
  if (!position_started_ || mode_ == ControlMode::position) return;
  hw::MotorSpeeds speeds;
  if (motors_enabled_) {
    double speed = command_.xspeed;
    double turn_rate = command_.yawspeed;
    if (mode_ == ControlMode::heading) {
      const double yaw = odometry_.reported().yaw * 180.0 / std::numbers::pi;
      const hw::BodyVelocity steered = hw::heading_control(speed, turn_rate, command_.yaw - yaw);
      speed = steered.speed_mm_s;
      turn_rate = steered.turn_rate_deg_s;
    }
    speeds = hw::motor_speeds(speed, turn_rate, params_);
  }
  if (!even_if_unchanged && speeds_sent_ == speeds) return;
  exchange_both(hw::set_speed, speeds.left, speeds.right);
  speeds_sent_ = speeds;
}

void RebConnection::poll() {
  next_cycle_ = Clock::now() + kCyclePeriod;
  // Heading control steers by the odometry: the set-points follow it.
  if (mode_ == ControlMode::heading) send_motor_speeds(false);
  // A command that arrives meanwhile goes out after the exchange under way,
  // not after the whole poll.
  if (has(RebRole::ir)) {
    ir_readings_ = exchange(hw::read_ir()).values;
    take_commands();
  }
  if (has(RebRole::power)) {
    const hw::Reply reply = exchange(hw::read_analog(hw::kBatteryChannel));
    if (!reply.values.empty()) battery_reading_ = reply.values.front();
    take_commands();
  }
  if (position_started_) {
    if (mode_ == ControlMode::position) {
      const hw::Reply status = exchange(hw::read_motion_status(hw::Motor::right));
      on_target_ = !status.values.empty() && status.values.front() == 1;
      take_commands();
    }
    read_odometry();
  }
}

void RebConnection::read_odometry() {
  const hw::Reply left = exchange(hw::read_position(hw::Motor::left));
  const Clock::time_point left_at = Clock::now();
  const hw::Reply right = exchange(hw::read_position(hw::Motor::right));
  const Clock::time_point right_at = Clock::now();
  if (left.values.empty() || right.values.empty()) return;
  const CounterReading left_now{left.values.front(), left_at};
  const CounterReading right_now{right.values.front(), right_at};
  if (left_counter_ && right_counter_) {
    // 32-bit counters: the difference wraps with them.
    const auto step = [](std::int32_t now_value, std::int32_t before) {
      return static_cast<std::int32_t>(static_cast<std::uint32_t>(now_value) - static_cast<std::uint32_t>(before));
    };
    const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
    // The right counter moved on while the left one's reply came back: a
    // robot driving straight would seem to turn at every start and stop.
    const double right_step = step(right_now.value, right_counter_->value);
    // Faster than any wheel turns: the counters restarted (a board reset), not motion.
    const double most = 2.0 * params_.max_wheel_speed_mm_s * params_.pulses_per_mm *
                            seconds(right_now.at - left_counter_->at) + 100.0;
    if (std::abs(step(left_now.value, left_counter_->value)) > most || std::abs(right_step) > most) {
      left_counter_ = left_now;
      right_counter_ = right_now;
      right_lag_ = 0.0;
      return;
    }
    const double span = seconds(right_now.at - right_counter_->at);
    const double share = span > 0.0 ? std::clamp(seconds(left_now.at - right_counter_->at) / span, 0.0, 1.0) : 1.0;
    const double right_at_left_time = right_step * share;
    const double left_pulses = step(left_now.value, left_counter_->value);
    const double right_pulses = right_at_left_time - right_lag_;
    right_lag_ = right_at_left_time - right_step;
    // The right motor counts backwards.
    const double left_mm = left_pulses / params_.pulses_per_mm;
    const double right_mm = -right_pulses / params_.pulses_per_mm;
    const double distance = (left_mm + right_mm) / 2.0 / 1000.0;
    const double turn = (right_mm - left_mm) / params_.axle_length_mm;
    odometry_.drive(distance, turn);
    // Real elapsed time: 1.5 divided by whole 10 ms units, by zero for a fast loop.
    const double elapsed = seconds(left_now.at - left_counter_->at);
    if (elapsed > 0.0) velocity_ = {distance / elapsed, 0.0, turn / elapsed};
  } else {
    right_lag_ = 0.0;
  }
  left_counter_ = left_now;
  right_counter_ = right_now;
}

void RebConnection::publish() {
  if (views_.empty()) return;
  const core::Timestamp stamp = views_.front().device->clock().now();
  for (const View& view : views_) {
    std::vector<std::uint8_t> payload;
    switch (view.role) {
      case RebRole::position: {
        if (!position_started_) continue;
        // 1.5 reported a finished position move as stall (reb.md §3.3).
        const bool stalled = mode_ == ControlMode::position && on_target_;
        payload = protocol::encode(interfaces::position_data(odometry_.reported(), velocity_, stalled,
                                                             interfaces::HeadingRange::from_0_to_360));
        break;
      }
      case RebRole::ir: {
        protocol::IrData data;
        const std::size_t count = std::min(ir_readings_.size(), data.voltages.size());
        for (std::size_t i = 0; i < count; ++i) {
          data.voltages[i] = static_cast<std::uint16_t>(std::clamp(ir_readings_[i] * hw::kIrMillivoltsPerStep, 0, 65535));
        }
        data.range_count = static_cast<std::uint16_t>(count);
        payload = protocol::encode(data);
        break;
      }
      case RebRole::power:
        if (!battery_reading_) continue;
        payload = protocol::encode(protocol::PowerData{.charge = hw::battery_decivolts(*battery_reading_)});
        break;
    }
    view.device->publish(std::move(payload), stamp);
  }
}

}  // namespace playerkit::drivers::reb
