#include "families/reb/emulator/reb_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

namespace playerkit::emulators {

namespace reb = hardware::reb;
using namespace std::chrono_literals;

namespace {

constexpr Duration kMotorPeriod = 10ms;
// 38400 baud, 8 data bits and 2 stop bits: 11 bits a character.
constexpr Duration kCharacterTime = std::chrono::nanoseconds(1'000'000'000LL * 11 / 38400);
constexpr Duration kShortestTurnaround = 2ms;
// The board calls a move done within this many pulses of its target.
constexpr double kOnTargetPulses = 2.0;
// An IR sensor's output falls with distance roughly as 1/d (Sharp-style):
// 2.5 V at 10 cm.
constexpr double kIrMillivoltMetres = 250.0;
constexpr double kIrMostMillivolts = 2500.0;

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

std::int32_t counter_value(double counter) {
  // A 32-bit counter wraps as the board's does.
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::int64_t>(std::llround(counter))));
}

std::vector<geometry::Pose2> ir_poses(const reb::RebParams& params) {
  std::vector<geometry::Pose2> poses;
  for (const auto& [x, y, heading] : params.ir_poses) {
    poses.push_back({x / 1000.0, y / 1000.0, geometry::normalize_angle(heading * std::numbers::pi / 180.0)});
  }
  return poses;
}

mobile_base::DriveGeometry drive_geometry(const reb::RebParams& params) {
  const double top_speed = params.max_wheel_speed_mm_s / 1000.0;
  return {.wheelbase = params.axle_length_mm / 1000.0,
          .footprint_radius = params.robot_radius_mm / 1000.0,
          .max_speed = top_speed,
          .max_turn_rate = 2.0 * top_speed / (params.axle_length_mm / 1000.0)};
}

}  // namespace

RebEmulator::RebEmulator(RebEmulatorOptions options)
    : params_(reb::params_for(options.subclass)),
      options_(std::move(options)),
      drive_(drive_geometry(params_), options_.body.odometry_error, options_.map, options_.body.initial_pose),
      ir_ring_(ir_poses(params_)) {}

const RebEmulator::Motor& RebEmulator::motor(reb::Motor which) const {
  return which == reb::Motor::left ? left_ : right_;
}

RebEmulator::Motor* RebEmulator::motor_numbered(std::int32_t number) {
  if (number == static_cast<std::int32_t>(reb::Motor::left)) return &left_;
  if (number == static_cast<std::int32_t>(reb::Motor::right)) return &right_;
  return nullptr;
}

void RebEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);
  for (const std::uint8_t byte : bytes) {
    if (byte == '\r' || byte == '\n') {
      // A lone CR (1.5's "restart") or the LF of a CR LF is an empty line.
      if (!partial_line_.empty()) handle_line(partial_line_, now);
      partial_line_.clear();
    } else if (partial_line_.size() < reb::kLongestLine) {
      partial_line_.push_back(static_cast<char>(byte));
    }
  }
}

void RebEmulator::handle_line(const std::string& line, Duration now) {
  std::vector<Telegram> telegrams;
  std::size_t characters = line.size() + 1;
  if (const auto command = reb::parse_command(line)) {
    if (const auto reply = answer(*command)) {
      const std::string text = reb::reply_text(*reply) + "\r\n";
      characters += text.size();
      telegrams.push_back({bytes_of(text), false});
    }
  }
  telegrams.push_back({bytes_of(":\r\n"), false});
  characters += 3;
  Duration due = now + std::max(kShortestTurnaround, kCharacterTime * static_cast<long>(characters));
  // The board answers one line after the other.
  if (!pending_.empty()) due = std::max(due, pending_.back().due);
  pending_.push_back({due, std::move(telegrams)});
}

std::optional<reb::Reply> RebEmulator::answer(const reb::Command& command) {
  const auto& arguments = command.arguments;
  const auto argument = [&](std::size_t index) { return index < arguments.size() ? arguments[index] : 0; };
  Motor* motor = arguments.empty() ? nullptr : motor_numbered(arguments[0]);
  const char letter = reb::reply_letter(command.letter);
  const bool was_moving = moving();
  std::optional<reb::Reply> reply;
  switch (command.letter) {
    case 'D':
      if (!motor || arguments.size() != 2) return std::nullopt;
      motor->target.reset();
      motor->speed = argument(1);
      reply = reb::Reply{letter, {}};
      break;
    case 'E':
      if (!motor) return std::nullopt;
      reply = reb::Reply{letter, {motor->speed}};
      break;
    case 'C':
      if (!motor || arguments.size() != 2) return std::nullopt;
      motor->target = argument(1);
      reply = reb::Reply{letter, {}};
      break;
    case 'G':
      if (!motor || arguments.size() != 2) return std::nullopt;
      motor->counter = argument(1);
      if (motor->target) motor->target = argument(1);  // a move under way ends where it is
      reply = reb::Reply{letter, {}};
      break;
    case 'H':
      if (!motor) return std::nullopt;
      reply = reb::Reply{letter, {counter_value(motor->counter)}};
      break;
    case 'K': {
      if (!motor) return std::nullopt;
      const double error = motor->target ? *motor->target - motor->counter : 0.0;
      const bool on_target = std::abs(error) <= kOnTargetPulses;
      reply = reb::Reply{letter, {on_target ? 1 : 0, motor->target ? 1 : 0, static_cast<std::int32_t>(std::lround(error))}};
      break;
    }
    case 'J':
      if (!motor || arguments.size() != 3) return std::nullopt;
      motor->profile_speed = std::max(1, std::abs(argument(1)));
      motor->profile_acceleration = argument(2);
      reply = reb::Reply{letter, {}};
      break;
    case 'A':
    case 'F':
      if (!motor || arguments.size() != 4) return std::nullopt;
      reply = reb::Reply{letter, {}};
      break;
    case 'I':
      if (arguments.size() != 1) return std::nullopt;
      reply = reb::Reply{letter, {argument(0) == reb::kBatteryChannel ? reb::battery_reading(options_.battery_volts) : 0}};
      break;
    case 'W': {
      reb::Reply readings{letter, {}};
      for (int i = 0; i < ir_ring_.size(); ++i) readings.values.push_back(ir_reading(i));
      reply = readings;
      break;
    }
    case 'Y':
      ir_on_ = argument(0) != 0;
      reply = reb::Reply{letter, {}};
      break;
    case 'Q':
      reply = reb::Reply{letter, {}};
      break;
    default:
      return std::nullopt;
  }
  if (!was_moving && moving()) next_tick_ = now_ + kMotorPeriod;
  ++answered_;
  return reply;
}

std::int32_t RebEmulator::ir_reading(int index) const {
  if (!ir_on_) return 0;
  const double range = ir_ring_.range(index, options_.map, drive_.true_pose(), options_.ir_range);
  if (range >= options_.ir_range) return 0;
  const double millivolts = std::min(kIrMostMillivolts, kIrMillivoltMetres / std::max(range, 1e-3));
  return static_cast<std::int32_t>(std::lround(millivolts / reb::kIrMillivoltsPerStep));
}

bool RebEmulator::moving() const {
  const auto motor_moving = [](const Motor& motor) {
    return motor.target ? std::abs(*motor.target - motor.counter) > 0.5 : motor.speed != 0;
  };
  return motor_moving(left_) || motor_moving(right_) || drive_.commanded_to_move();
}

void RebEmulator::tick() {
  for (Motor* motor : {&left_, &right_}) {
    if (!motor->target) continue;
    const double remaining = *motor->target - motor->counter;
    const double step = std::clamp(remaining, -static_cast<double>(motor->profile_speed),
                                   static_cast<double>(motor->profile_speed));
    motor->speed = static_cast<std::int32_t>(std::lround(step));
  }
  const double left = reb::mm_per_s(left_.speed, params_) / 1000.0;
  const double right = -reb::mm_per_s(right_.speed, params_) / 1000.0;
  drive_.command_wheels({left, right});
  const geometry::Pose2 before = drive_.odometry();
  drive_.run(std::chrono::duration<double>(kMotorPeriod).count(), 0.01);
  const geometry::Pose2 moved = before.between(drive_.odometry());
  // The encoders count what the odometry saw (a stalled robot's wheels do not turn).
  const double half_turn_mm = moved.yaw * params_.axle_length_mm / 2.0;
  left_.counter += (moved.x * 1000.0 - half_turn_mm) * params_.pulses_per_mm;
  right_.counter -= (moved.x * 1000.0 + half_turn_mm) * params_.pulses_per_mm;
  for (Motor* motor : {&left_, &right_}) {
    if (motor->target && std::abs(*motor->target - motor->counter) <= 0.5) motor->speed = 0;
  }
}

void RebEmulator::advance(Duration now) {
  while (moving() && next_tick_ <= now) {
    now_ = next_tick_;
    tick();
    next_tick_ += kMotorPeriod;
  }
  if (!moving()) drive_.stop();
  now_ = std::max(now_, now);
  if (!moving()) next_tick_ = now_ + kMotorPeriod;
  while (!pending_.empty() && pending_.front().due <= now) {
    for (Telegram& telegram : pending_.front().telegrams) output_.push_back(std::move(telegram));
    pending_.pop_front();
  }
}

Duration RebEmulator::next_deadline() const {
  Duration next = Duration::max();
  if (!pending_.empty()) next = pending_.front().due;
  if (moving()) next = std::min(next, next_tick_);
  return next;
}

std::vector<Telegram> RebEmulator::take_output() { return std::exchange(output_, {}); }

std::string RebEmulator::describe() const {
  std::ostringstream out;
  out << "REB UBot (" << params_.subclass << "), IR " << (ir_on_ ? "on" : "off") << ", battery "
      << options_.battery_volts << " V";
  // The wheels and the true pose, as the other robots' emulators show them: what a
  // driver's odometry is checked against (docs/reference-checks).
  const geometry::Pose2& pose = drive_.true_pose();
  char where[120];
  std::snprintf(where, sizeof where, ", wheels %d/%d pulses/10 ms, at (%.2f, %.2f, %.0f deg)", left_.speed, right_.speed,
                pose.x, pose.y, pose.yaw * 180.0 / std::numbers::pi);
  out << where;
  return out.str();
}

}  // namespace playerkit::emulators
