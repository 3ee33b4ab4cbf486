#include "families/er1/emulator/er1_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "families/er1/protocol/er1_frame_format.hpp"

namespace playerkit::emulators {

namespace er1 = hardware::er1;
using namespace std::chrono_literals;

namespace {

// How finely motion is worked out: the counts are read about every 10 ms.
constexpr double kMotionStep = 0.01;
constexpr Duration kMotionTick = 20ms;

// An ER1 carries no speed limit of its own in the sheet; these keep a
// runaway command physical: 1 m/s and one turn a second.
mobile_base::DriveGeometry er1_geometry(double axle) {
  return {.wheelbase = axle, .footprint_radius = 0.3, .max_speed = 1.0, .max_turn_rate = 2.0 * 3.14159265358979};
}

double wheel_metres_per_second(std::int32_t speed_register) {
  return er1::millimetres_per_second(speed_register) / 1000.0;
}

std::int32_t argument32(std::span<const std::uint8_t> command) {
  const std::uint32_t value = (std::uint32_t{command[4]} << 24) | (std::uint32_t{command[5]} << 16) |
                              (std::uint32_t{command[6]} << 8) | std::uint32_t{command[7]};
  return static_cast<std::int32_t>(value);
}

}  // namespace

Er1Emulator::Er1Emulator(Er1EmulatorOptions options)
    : options_(options),
      drive_(er1_geometry(options.axle), options.odometry_error, options.map, options.initial_pose) {
  if (!(options_.axle > 0.0)) throw std::invalid_argument("er1 emulator: the axle must be above 0 m");
  if (options_.left_motor_port != 0 && options_.left_motor_port != 1) {
    throw std::invalid_argument("er1 emulator: the left motor is on port 0 or 1");
  }
}

void Er1Emulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);  // a position read reports where the wheels are now
  pending_.insert(pending_.end(), bytes.begin(), bytes.end());
  const er1::CommandFormat format;
  std::size_t start = 0;
  while (start < pending_.size()) {
    const auto scan = format.scan(std::span(pending_).subspan(start));
    if (scan.kind == framing::FrameScan::Kind::need_more) break;
    if (scan.kind == framing::FrameScan::Kind::frame) obey(std::span(pending_).subspan(start, scan.length));
    start += scan.length;  // noise: the RCM drops what it cannot read
  }
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(start));
}

void Er1Emulator::obey(std::span<const std::uint8_t> command) {
  ++commands_;
  const std::uint8_t op = command[3];
  const std::size_t reply_size = er1::reply_length(op);
  const std::vector<std::uint8_t> no_data(reply_size - 2, 0);
  if (!er1::sums_to_zero(command)) {
    ++bad_checksums_;
    output_.push_back({er1::reply(1, no_data), true});
    return;
  }
  MotorState& motor = motor_state(command[0] == 0 ? Motor::port0 : Motor::port1);
  er1::Bytes answer = er1::reply(0, no_data);
  switch (op) {
    case er1::opcode::init:
      ++inits_;
      answer = er1::init_reply();
      break;
    case er1::opcode::read_position:
      answer = er1::position_reply(count(command[0] == 0 ? Motor::port0 : Motor::port1));
      break;
    case er1::opcode::velocity:
      motor.latched = argument32(command);
      break;
    case er1::opcode::execute:
      ++executes_;
      motor.running = motor.latched;
      command_wheels();
      break;
    case er1::opcode::reset_position:
      motor.ticks = 0.0;
      break;
    case er1::opcode::voltage: {
      const std::uint8_t decivolts[] = {0x00, 120};  // a charged 12 V pack
      answer = er1::reply(0, decivolts);
      break;
    }
    default:
      break;  // modes and profiles whose meaning the sheet does not know: acknowledged
  }
  output_.push_back({std::move(answer), true});
}

void Er1Emulator::command_wheels() {
  // The left motor is mirrored: a negative register drives its wheel forward.
  drive_.command_wheels({.left = -wheel_metres_per_second(motor_state(left_port()).running),
                         .right = wheel_metres_per_second(motor_state(right_port()).running)});
}

bool Er1Emulator::moving() const { return drive_.commanded_to_move(); }

void Er1Emulator::advance(Duration now) {
  if (now <= now_) return;
  const double seconds = std::chrono::duration<double>(now - now_).count();
  now_ = now;
  if (moving()) run_for(seconds);
}

// The encoders count what the odometry model says the wheels did, so the
// configured odometry error reaches the host through the counts.
void Er1Emulator::run_for(double seconds) {
  constexpr double kTicksPerMetre = 1000.0 / er1::kMillimetresPerTick;
  while (seconds > 0.0) {
    const double step = std::min(seconds, kMotionStep);
    seconds -= step;
    const geometry::Pose2 before = drive_.odometry();
    drive_.run(step, step);
    const geometry::Pose2 after = drive_.odometry();
    const double rotation = geometry::normalize_angle(after.yaw - before.yaw);
    const double mid = before.yaw + rotation / 2.0;
    const double chord = (after.x - before.x) * std::cos(mid) + (after.y - before.y) * std::sin(mid);
    const double distance = std::abs(rotation) > 1e-9 ? chord * (rotation / 2.0) / std::sin(rotation / 2.0) : chord;
    const double left = distance - rotation * options_.axle / 2.0;
    const double right = distance + rotation * options_.axle / 2.0;
    motor_state(left_port()).ticks -= left * kTicksPerMetre;
    motor_state(right_port()).ticks += right * kTicksPerMetre;
  }
}

std::int32_t Er1Emulator::count(Motor motor) const {
  // A 32-bit register: it wraps.
  const double ticks = std::round(motor_state(motor).ticks);
  const double wrapped = ticks - 4294967296.0 * std::floor((ticks + 2147483648.0) / 4294967296.0);
  return static_cast<std::int32_t>(wrapped);
}

Duration Er1Emulator::next_deadline() const { return moving() ? now_ + kMotionTick : Duration::max(); }

std::vector<Telegram> Er1Emulator::take_output() { return std::exchange(output_, {}); }

std::string Er1Emulator::describe() const {
  char line[160];
  const geometry::Pose2& pose = drive_.true_pose();
  std::snprintf(line, sizeof line, "ER1, left motor on port %d, at (%.2f, %.2f, %.0f deg), %llu commands",
                options_.left_motor_port, pose.x, pose.y, pose.yaw * 180.0 / 3.14159265358979,
                static_cast<unsigned long long>(commands_));
  return line;
}

}  // namespace playerkit::emulators
