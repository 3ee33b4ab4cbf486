#include "families/trogdor/emulator/trogdor_emulator.hpp"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <utility>

#include "families/trogdor/protocol/trogdor_units.hpp"

namespace playerkit::emulators {

namespace trogdor = hardware::trogdor;
using namespace std::chrono_literals;

namespace {

// The body is integrated in steps no longer than this.
constexpr Duration kMotionStep = 10ms;
constexpr Duration kPartialMessageLifetime = 100ms;

double seconds(Duration duration) { return std::chrono::duration<double>(duration).count(); }

mobile_base::DriveGeometry trogdor_geometry() {
  return {.wheelbase = trogdor::kAxleLength,
          .footprint_radius = trogdor::kBodySize / 2,
          .max_speed = trogdor::kMaxWheelSpeed,
          .max_turn_rate = 2 * trogdor::kMaxWheelSpeed / trogdor::kAxleLength};
}

// A counter as the robot's int32 shows it: wrapping, and never exactly 0
// (the reference drops a reading with a zero count, trogdor.md §5.1).
std::int32_t counter(std::int32_t start, double ticks) {
  const auto value = static_cast<std::uint32_t>(start) + static_cast<std::uint32_t>(std::llround(ticks));
  return value == 0 ? 1 : static_cast<std::int32_t>(value);
}

}  // namespace

TrogdorEmulator::TrogdorEmulator(TrogdorEmulatorOptions options, const grid::OccupancyGrid* map)
    : options_(options), drive_(trogdor_geometry(), options.body.odometry_error, map, options.body.initial_pose) {}

void TrogdorEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) {
  advance(now);
  // Bytes sent at another speed arrive as garbage the cerebellum ignores.
  if (host_baud != 0 && host_baud != kBaud) return;
  if (!partial_.empty() && now - partial_since_ > kPartialMessageLifetime) partial_.clear();
  for (const std::uint8_t byte : bytes) {
    if (partial_.empty()) partial_since_ = now;
    partial_.push_back(byte);
    const std::size_t size = trogdor::host_message_size(partial_[0]);
    if (size == 0) {
      ++refused_;
      send({trogdor::kNack}, false);
      partial_.clear();
      continue;
    }
    // INIT is three exact bytes: any other second or third byte refuses it.
    if (partial_[0] == trogdor::message::init[0] && partial_.back() != trogdor::message::init[partial_.size() - 1]) {
      ++refused_;
      send({trogdor::kNack}, false);
      partial_.clear();
      continue;
    }
    if (partial_.size() < size) continue;
    execute(partial_);
    partial_.clear();
  }
}

void TrogdorEmulator::execute(const trogdor::Bytes& message) {
  ++messages_;
  if (message.size() == trogdor::kWheelPairMessageSize && !trogdor::xor_checks(message)) {
    ++refused_;
    send({trogdor::kNack}, false);
    return;
  }
  switch (message[0]) {
    case trogdor::message::init[0]:
      initialised_ = true;
      break;
    case trogdor::message::deinit:
      initialised_ = false;
      velocities_ = {};
      apply_velocities();
      break;
    case trogdor::message::set_velocities:
      velocities_ = {trogdor::get_int32(message, 1), trogdor::get_int32(message, 5)};
      apply_velocities();
      break;
    case trogdor::message::set_accelerations:
      accelerations_ = {trogdor::get_int32(message, 1), trogdor::get_int32(message, 5)};
      break;
    case trogdor::message::enable_velocity_control:
      enabled_ = true;
      apply_velocities();
      break;
    case trogdor::message::disable_velocity_control:
      enabled_ = false;
      apply_velocities();
      break;
    case trogdor::message::get_odometry: {
      trogdor::Bytes reply{trogdor::kAck};
      const trogdor::Bytes block = trogdor::odometry_block(reading());
      reply.insert(reply.end(), block.begin(), block.end());
      send(std::move(reply), true);
      return;
    }
    case trogdor::message::get_voltage: {
      trogdor::Bytes reply{trogdor::kAck};
      const trogdor::Bytes block = trogdor::voltage_block(options_.voltage);
      reply.insert(reply.end(), block.begin(), block.end());
      send(std::move(reply), true);
      return;
    }
    case trogdor::message::stop:
    case trogdor::message::kill:
      velocities_ = {};
      apply_velocities();
      break;
    default:  // heartbeat
      break;
  }
  send({trogdor::kAck}, false);
}

void TrogdorEmulator::apply_velocities() {
  const double unit = trogdor::metres_per_second_per_unit();
  if (!enabled_) {
    drive_.stop();
    return;
  }
  drive_.command_wheels({.left = velocities_.left * unit, .right = velocities_.right * unit});
}

trogdor::OdometryReading TrogdorEmulator::reading() const {
  const bool moving = enabled_ && drive_.commanded_to_move();
  const auto wheels = drive_.wheels();
  const double unit = trogdor::metres_per_second_per_unit();
  return {.left_count = counter(options_.start_count, left_ticks_),
          .right_count = counter(options_.start_count, right_ticks_),
          .left_velocity = moving ? static_cast<std::int32_t>(std::lround(wheels.left / unit)) : 0,
          .right_velocity = moving ? static_cast<std::int32_t>(std::lround(wheels.right / unit)) : 0,
          .encoder_error = options_.encoder_error};
}

void TrogdorEmulator::advance(Duration now) {
  if (now > now_) integrate(now);
}

// The wheels' ticks follow the odometry the body measured (its error
// included), so a host integrating the counters sees exactly that odometry.
void TrogdorEmulator::integrate(Duration until) {
  const double tick = trogdor::metres_per_tick();
  while (now_ < until) {
    const Duration step = std::min(kMotionStep, until - now_);
    const geometry::Pose2 before = drive_.odometry();
    drive_.run(seconds(step), seconds(kMotionStep));
    const geometry::Pose2 after = drive_.odometry();
    const double turn = geometry::angle_difference(after.yaw, before.yaw);
    const double heading = before.yaw + turn / 2;
    const double distance = (after.x - before.x) * std::cos(heading) + (after.y - before.y) * std::sin(heading);
    left_ticks_ += (distance - turn * trogdor::kAxleLength / 2) / tick;
    right_ticks_ += (distance + turn * trogdor::kAxleLength / 2) / tick;
    now_ += step;
  }
}

Duration TrogdorEmulator::next_deadline() const {
  // While it moves, the riders' scans want a fresh pose.
  return drive_.commanded_to_move() ? now_ + kMotionStep : Duration::max();
}

void TrogdorEmulator::send(trogdor::Bytes bytes, bool has_checksum) {
  output_.push_back({std::move(bytes), has_checksum});
}

std::vector<Telegram> TrogdorEmulator::take_output() { return std::exchange(output_, {}); }

std::string TrogdorEmulator::describe() const {
  const geometry::Pose2& pose = drive_.true_pose();
  char text[160];
  std::snprintf(text, sizeof text, "Trogdor, %s, motion %s, wheels %d/%d units, at (%.3f, %.3f, %.1f deg)",
                initialised_ ? "initialised" : "not initialised", enabled_ ? "enabled" : "disabled",
                velocities_.left, velocities_.right, pose.x, pose.y, pose.yaw * 180 / 3.14159265358979);
  return text;
}

}  // namespace playerkit::emulators
