#include "families/segwayrmp/emulator/segwayrmp_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "emulators/mobile_base/differential_drive.hpp"
#include "links/can/slcan.hpp"

namespace playerkit::emulators {

namespace rmp = hardware::segwayrmp;
namespace slcan = links::can;
using namespace std::chrono_literals;

namespace {

// The RMP 200: 610 mm wide, 508 mm long, tyres about 540 mm apart; the
// largest command is 8 mph and 1024 / 7.8 deg/s.
constexpr double kTrack = 0.54;
constexpr double kFootprintRadius = 0.40;
constexpr double kTopSpeed = rmp::kMaxTransCounts / rmp::kTransCountsPerMillimetrePerSecond / 1000.0;
constexpr double kTopTurnRate = rmp::kMaxRotCounts / rmp::kAngleCountsPerDegree * std::numbers::pi / 180.0;
constexpr Duration kMotionStep = 10ms;
constexpr std::uint8_t kFullScale = 16;

double seconds(Duration duration) { return std::chrono::duration<double>(duration).count(); }

std::uint32_t counter(double value, double counts_per_unit) {
  return static_cast<std::uint32_t>(static_cast<std::int64_t>(std::llround(value * counts_per_unit)));
}

std::int16_t counts16(double value) {
  return static_cast<std::int16_t>(std::clamp(std::rint(value), -32768.0, 32767.0));
}

void check(bool holds, const std::string& what) {
  if (!holds) throw std::invalid_argument("segwayrmp emulator: " + what);
}

}  // namespace

SegwayRmpEmulator::SegwayRmpEmulator(SegwayRmpEmulatorOptions options) : options_(options) {
  check(options_.status_rate >= 1 && options_.status_rate <= 1000, "the status rate must be 1 to 1000 Hz");
  check(options_.watchdog >= 0, "the watchdog must be 0 (off) or more seconds");
  check(options_.max_acceleration >= 0, "the acceleration limit must be 0 (none) or more");
  drive_ = std::make_unique<mobile_base::DifferentialDrive>(
      mobile_base::DriveGeometry{.wheelbase = kTrack,
                                 .footprint_radius = kFootprintRadius,
                                 .max_speed = kTopSpeed,
                                 .max_turn_rate = kTopTurnRate},
      options_.odometry_error, options_.map, options_.initial_pose);
  last_odometry_ = drive_->odometry();
}

SegwayRmpEmulator::~SegwayRmpEmulator() = default;

std::optional<geometry::Pose2> SegwayRmpEmulator::world_pose() const { return drive_->true_pose(); }
double SegwayRmpEmulator::commanded_speed() const { return drive_->commanded_speed(); }
double SegwayRmpEmulator::commanded_turn_rate() const { return drive_->commanded_turn_rate(); }

std::uint8_t SegwayRmpEmulator::scale(rmp::StatusCommand which) const {
  switch (which) {
    case rmp::StatusCommand::velocity_scale:
      return velocity_scale_;
    case rmp::StatusCommand::acceleration_scale:
      return acceleration_scale_;
    case rmp::StatusCommand::turn_scale:
      return turn_scale_;
    case rmp::StatusCommand::gain_schedule:
      return gain_schedule_;
    case rmp::StatusCommand::current_limit:
      return current_limit_;
    default:
      return 0;
  }
}

// ---------------------------------------------------------------- the adapter

void SegwayRmpEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);
  for (const std::uint8_t byte : bytes) {
    if (byte != static_cast<std::uint8_t>(slcan::kSlcanEnd)) {
      // A runaway line is cut where the adapter's buffer ends.
      if (typed_.size() < slcan::kLongestSlcanLine) typed_.push_back(static_cast<char>(byte));
      continue;
    }
    const std::string line = std::move(typed_);
    typed_.clear();
    if (!line.empty()) execute(line);
  }
}

void SegwayRmpEmulator::reply(const std::string& text) {
  output_.push_back({std::vector<std::uint8_t>(text.begin(), text.end()), false});
}

void SegwayRmpEmulator::execute(const std::string& line) {
  const std::string accepted(1, slcan::kSlcanEnd);
  const std::string refused(1, slcan::kSlcanRefusal);
  switch (line.front()) {
    case 'S': {
      const auto rate = line.size() == 2 ? slcan::slcan_bitrate_of(line[1]) : std::nullopt;
      if (!rate || open_) return reply(refused);
      bitrate_ = *rate;
      return reply(accepted);
    }
    case 'O':
      if (open_ || line.size() != 1) return reply(refused);
      open_ = true;
      shut_down_ = false;  // a robot powered down comes back with a new session
      next_status_ = now_;
      return reply(accepted);
    case 'C':
      if (!open_ || line.size() != 1) return reply(refused);
      open_ = false;
      return reply(accepted);
    case 'V':
      return reply("V1013\r");
    case 'N':
      return reply("NRMP1\r");
    case 't':
    case 'T': {
      const auto frame = slcan::parse_slcan_frame(line);
      if (!open_ || !frame) return reply(refused);
      reply(line.front() == 't' ? "z\r" : "Z\r");
      return take_frame(*frame);
    }
    default:
      return reply(refused);
  }
}

void SegwayRmpEmulator::take_frame(const framing::CanFrame& frame) {
  if (frame.id == rmp::kShutdownId && !frame.extended) {
    set_target(0, 0);
    shut_down_ = true;
    return;
  }
  if (const auto command = rmp::parse_command(frame)) apply(*command);
}

void SegwayRmpEmulator::apply(const rmp::Command& command) {
  ++commands_;
  last_command_ = now_;
  if (shut_down_) return;
  const std::uint8_t value = command.status_value;
  switch (command.status) {
    case rmp::StatusCommand::velocity_scale:
      velocity_scale_ = std::min(value, kFullScale);
      break;
    case rmp::StatusCommand::acceleration_scale:
      acceleration_scale_ = std::min(value, kFullScale);
      break;
    case rmp::StatusCommand::turn_scale:
      turn_scale_ = std::min(value, kFullScale);
      break;
    case rmp::StatusCommand::gain_schedule:
      gain_schedule_ = value;
      break;
    case rmp::StatusCommand::current_limit:
      current_limit_ = value;
      break;
    case rmp::StatusCommand::reset_integrators:
      if ((value & rmp::kResetRightWheel) != 0) right_wheel_ = 0;
      if ((value & rmp::kResetLeftWheel) != 0) left_wheel_ = 0;
      if ((value & rmp::kResetYaw) != 0) yaw_ = 0;
      if ((value & rmp::kResetForeAft) != 0) fore_aft_ = 0;
      break;
    default:
      break;
  }
  const double speed = command.trans / rmp::kTransCountsPerMillimetrePerSecond / 1000.0;
  const double turn_rate = command.rot / rmp::kAngleCountsPerDegree * std::numbers::pi / 180.0;
  set_target(speed * velocity_scale_ / kFullScale, turn_rate * turn_scale_ / kFullScale);
}

void SegwayRmpEmulator::set_target(double speed, double turn_rate) {
  target_speed_ = speed;
  target_turn_rate_ = turn_rate;
  watchdog_stopped_ = false;
}

// ---------------------------------------------------------------- time

void SegwayRmpEmulator::advance(Duration now) {
  while (open_ && !shut_down_ && next_status_ <= now) {
    move_to(next_status_);
    send_status();
    next_status_ += std::chrono::duration_cast<Duration>(std::chrono::duration<double>(1.0 / options_.status_rate));
  }
  move_to(now);
}

Duration SegwayRmpEmulator::next_deadline() const {
  if (open_ && !shut_down_) return next_status_;
  if (drive_->commanded_to_move() || target_speed_ != 0 || target_turn_rate_ != 0) return now_ + kMotionStep;
  return Duration::max();
}

void SegwayRmpEmulator::move_to(Duration now) {
  while (now_ < now) {
    const Duration step = std::min(kMotionStep, now - now_);
    now_ += step;
    const double dt = seconds(step);
    const bool asked_to_move = target_speed_ != 0 || target_turn_rate_ != 0;
    if (options_.watchdog > 0 && asked_to_move && seconds(now_ - last_command_) > options_.watchdog) {
      set_target(0, 0);
      watchdog_stopped_ = true;
      ++watchdog_stops_;
    }
    double speed = target_speed_;
    if (options_.max_acceleration > 0) {
      const double allowed = options_.max_acceleration * acceleration_scale_ / kFullScale * dt;
      const double current = drive_->commanded_speed();
      speed = std::clamp(target_speed_, current - allowed, current + allowed);
    }
    drive_->command(speed, target_turn_rate_);
    drive_->run(dt, dt);
    const geometry::Pose2 moved = last_odometry_.between(drive_->odometry());
    last_odometry_ = drive_->odometry();
    fore_aft_ += moved.x;
    yaw_ += moved.yaw;
    left_wheel_ += moved.x - moved.yaw * kTrack / 2;
    right_wheel_ += moved.x + moved.yaw * kTrack / 2;
  }
}

void SegwayRmpEmulator::send_status() {
  const mobile_base::WheelVelocities wheels = drive_->wheels();
  const double turn_degrees = (wheels.right - wheels.left) / kTrack * 180.0 / std::numbers::pi;
  status_.battery = static_cast<std::uint16_t>(std::clamp(std::rint(options_.battery_percent), 0.0, 65535.0));
  status_.pitch = counts16(options_.pitch_degrees * rmp::kAngleCountsPerDegree);
  status_.pitch_rate = 0;
  status_.roll = 0;
  status_.roll_rate = 0;
  status_.left_wheel_velocity = counts16(wheels.left * rmp::kWheelCountsPerMetrePerSecond);
  status_.right_wheel_velocity = counts16(wheels.right * rmp::kWheelCountsPerMetrePerSecond);
  status_.yaw_rate = counts16(-turn_degrees * rmp::kAngleCountsPerDegree);  // the RMP's clockwise-positive rate
  ++status_.frame_counter;
  status_.left_wheel_displacement = counter(left_wheel_, rmp::kForeAftCountsPerMetre);
  status_.right_wheel_displacement = counter(right_wheel_, rmp::kForeAftCountsPerMetre);
  status_.fore_aft_displacement = counter(fore_aft_, rmp::kForeAftCountsPerMetre);
  status_.yaw_displacement = counter(yaw_ / (2 * std::numbers::pi), rmp::kYawCountsPerRevolution);
  for (const framing::CanFrame& frame : rmp::status_frames(status_)) reply(slcan::slcan_frame_line(frame));
  ++status_sets_;
}

std::vector<Telegram> SegwayRmpEmulator::take_output() { return std::exchange(output_, {}); }

std::string SegwayRmpEmulator::describe() const {
  std::string text = "Segway RMP on slcan, ";
  text += open_ ? "channel open at " + std::to_string(bitrate_ / 1000) + " kbit/s" : "channel closed";
  if (shut_down_) text += ", shut down";
  if (watchdog_stopped_) text += ", stopped by its watchdog";
  text += ", " + std::to_string(status_sets_) + " status sets, " + std::to_string(commands_) + " commands";
  // The true pose, what a driver's odometry is checked against (docs/reference-checks).
  const geometry::Pose2& pose = drive_->true_pose();
  char where[80];
  std::snprintf(where, sizeof where, ", at (%.2f, %.2f, %.0f deg)", pose.x, pose.y, pose.yaw * 180.0 / std::numbers::pi);
  text += where;
  return text;
}

}  // namespace playerkit::emulators
