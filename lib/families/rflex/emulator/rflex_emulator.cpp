#include "families/rflex/emulator/rflex_emulator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <utility>

#include "families/rflex/protocol/rflex_packet.hpp"

namespace playerkit::emulators::rflex {

namespace hw = hardware::rflex;
using namespace std::chrono_literals;

namespace {

// Sensors report with the motion burst; without motion reports this period.
constexpr Duration kSensorPeriod = 100ms;
// Motion is integrated in steps no longer than this.
constexpr double kMaxStep = 0.01;
constexpr std::uint8_t kFirstBumperAddress = 0x40;
constexpr std::uint16_t kPanelPressed = 0x0F;

double seconds(Duration d) { return std::chrono::duration<double>(d).count(); }

std::vector<geometry::Pose2> sonar_poses(const RflexModel& model, std::vector<std::uint8_t>& ids) {
  int count = 0;
  for (std::size_t board = 0; board < model.sonars_in_bank.size(); ++board) {
    for (int channel = 0; channel < model.sonars_in_bank[board]; ++channel, ++count) {
      ids.push_back(static_cast<std::uint8_t>(16 * board + static_cast<std::size_t>(channel)));
    }
  }
  return mobile_base::evenly_spaced_ring(count, model.radius, 0.0, mobile_base::RingOrder::counter_clockwise);
}

}  // namespace

RflexEmulator::RflexEmulator(RflexEmulatorOptions options)
    : options_(std::move(options)),
      drive_({options_.model.wheelbase, options_.model.radius, options_.model.max_speed, options_.model.max_turn_rate},
             options_.odometry_error, options_.map, options_.initial_pose),
      sonar_ring_(sonar_poses(options_.model, sonar_ids_)),
      ir_ring_(mobile_base::evenly_spaced_ring(8 * options_.model.ir_banks, options_.model.radius, 0.0,
                                               mobile_base::RingOrder::counter_clockwise)),
      braked_(options_.brake_at_start),
      bumpers_(static_cast<std::size_t>(options_.model.bumper_panels), 0),
      bumpers_reported_(bumpers_.size(), 0),
      pressed_by_hand_(bumpers_.size()) {}

std::int32_t RflexEmulator::distance_counter() const {
  return static_cast<std::int32_t>(static_cast<std::int64_t>(std::llround(distance_units_)));
}

std::int32_t RflexEmulator::bearing_counter() const {
  return static_cast<std::int32_t>(static_cast<std::int64_t>(std::llround(bearing_units_)));
}

std::uint32_t RflexEmulator::timestamp() const {
  return static_cast<std::uint32_t>(std::chrono::duration_cast<std::chrono::milliseconds>(now_).count());
}

void RflexEmulator::send(const hw::Packet& packet) {
  hw::Packet stamped = packet;
  stamped.id = next_id_++;
  output_.push_back({hw::encode_packet(stamped), true});
}

void RflexEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);
  input_.insert(input_.end(), bytes.begin(), bytes.end());
  const hw::RflexFrameFormat format;
  std::size_t used = 0;
  while (used < input_.size()) {
    const auto scan = format.scan(std::span(input_).subspan(used));
    if (scan.kind == framing::FrameScan::Kind::need_more) break;
    if (scan.kind == framing::FrameScan::Kind::frame) {
      if (const auto packet = hw::decode_packet(std::span(input_).subspan(used, scan.length))) execute(*packet);
    }
    used += scan.length;  // a bad checksum is dropped whole, noise byte by byte
  }
  input_.erase(input_.begin(), input_.begin() + static_cast<std::ptrdiff_t>(used));
}

void RflexEmulator::execute(const hw::Packet& packet) {
  ++commands_;
  if (const auto axis = hw::read_axis_command(packet)) {
    if (axis->axis <= 1) {
      velocity_[axis->axis] = static_cast<std::int64_t>(axis->velocity) * (axis->positive ? 1 : -1);
      last_velocity_command_ = now_;
      ++velocity_commands_;
    }
    return;
  }
  if (packet.port == hw::port::motion && packet.opcode == hw::opcode::mot_system_report_req) {
    if (const auto request = hw::read_report_request(packet)) {
      motion_period_ = std::chrono::microseconds(request->period);
      axis_mask_ = request->axis_mask;
      next_report_ = now_ + (reporting_motion() ? motion_period_ : kSensorPeriod);
    }
    return;
  }
  if (packet.port == hw::port::dio && packet.opcode == hw::opcode::dio_reports_req) {
    if (const auto request = hw::read_report_request(packet)) {
      dio_on_ = request->period != 0;
      if (dio_on_) {
        // Where every panel stands now, then only changes.
        for (std::size_t i = 0; i < bumpers_.size(); ++i) {
          send(hw::dio_report({timestamp(), static_cast<std::uint8_t>(kFirstBumperAddress + i), bumpers_[i]}, 0));
          bumpers_reported_[i] = bumpers_[i];
        }
      }
    }
    return;
  }
  if (const auto run = hw::read_sonar_run(packet)) {
    sonar_on_ = run->mode != 0;
    if (next_report_ == Duration::max()) next_report_ = now_ + kSensorPeriod;
    return;
  }
  if (const auto on = hw::read_ir_run(packet)) {
    ir_on_ = *on;
    if (next_report_ == Duration::max()) next_report_ = now_ + kSensorPeriod;
    return;
  }
  if (packet.port == hw::port::motion) {
    switch (packet.opcode) {
      case hw::opcode::mot_set_defaults: velocity_[0] = velocity_[1] = 0; break;
      case hw::opcode::mot_brake_set: braked_ = true; break;
      case hw::opcode::mot_brake_release: braked_ = false; break;
      default: break;  // opcodes the driver never sends
    }
    return;
  }
  if (packet.port == hw::port::system && packet.opcode == hw::opcode::sys_status) {
    send(hw::system_status({timestamp(), options_.model.battery_centivolts, static_cast<std::uint8_t>(braked_)}, 0));
    return;
  }
  if (packet.port == hw::port::joystick && packet.opcode == hw::opcode::jstk_get_state) {
    hw::JoystickState state = joystick_;
    state.timestamp = timestamp();
    send(hw::joystick_state(state, 0));
  }
}

void RflexEmulator::move_to(Duration now) {
  if (now <= now_) return;
  if (options_.failsafe > 0.0 && (velocity_[0] != 0 || velocity_[1] != 0)) {
    const Duration silence_ends =
        last_velocity_command_ + std::chrono::duration_cast<Duration>(std::chrono::duration<double>(options_.failsafe));
    if (now > silence_ends) {
      if (silence_ends > now_) move_to(silence_ends);
      velocity_[0] = velocity_[1] = 0;  // the failsafe: nobody is commanding
    }
  }
  const RflexModel& model = options_.model;
  if (braked_) {
    drive_.stop();
  } else {
    drive_.command(static_cast<double>(velocity_[0]) / model.odo_distance_conversion / 1000.0,
                   static_cast<double>(velocity_[1]) / model.odo_angle_conversion);
  }
  double left = seconds(now - now_);
  while (left > 0.0) {
    const double step = std::min(left, kMaxStep);
    const geometry::Pose2 before = drive_.odometry();
    drive_.run(step, step);
    const geometry::Pose2 after = drive_.odometry();
    const double turn = geometry::normalize_angle(after.yaw - before.yaw);
    const double dx = after.x - before.x, dy = after.y - before.y;
    const double heading = before.yaw + turn / 2.0;
    const double along = dx * std::cos(heading) + dy * std::sin(heading);
    const double length = std::hypot(dx, dy);
    distance_units_ += (along >= 0 ? length : -length) * 1000.0 * model.odo_distance_conversion;
    bearing_units_ += turn * model.odo_angle_conversion;
    left -= step;
  }
  now_ = now;
  update_bumpers();
}

void RflexEmulator::update_bumpers() {
  std::fill(bumpers_.begin(), bumpers_.end(), 0);
  const mobile_base::Contact contact = drive_.take_contact();
  if (contact.stalled && !bumpers_.empty()) {
    // Panels evenly around the body, panel 0 centred ahead, counter-clockwise.
    const double width = 2.0 * std::numbers::pi / static_cast<double>(bumpers_.size());
    double at = std::fmod(contact.bearing + width / 2.0, 2.0 * std::numbers::pi);
    if (at < 0) at += 2.0 * std::numbers::pi;
    bumpers_[std::min(bumpers_.size() - 1, static_cast<std::size_t>(at / width))] = kPanelPressed;
  }
  for (std::size_t i = 0; i < bumpers_.size(); ++i) {
    if (pressed_by_hand_[i]) bumpers_[i] = *pressed_by_hand_[i];
    if (dio_on_ && bumpers_[i] != bumpers_reported_[i]) {
      send(hw::dio_report({timestamp(), static_cast<std::uint8_t>(kFirstBumperAddress + i), bumpers_[i]}, 0));
      bumpers_reported_[i] = bumpers_[i];
    }
  }
}

void RflexEmulator::press_bumper(int panel, std::uint16_t corners) {
  if (panel < 0 || panel >= static_cast<int>(bumpers_.size())) return;
  pressed_by_hand_[static_cast<std::size_t>(panel)] =
      corners == 0 ? std::nullopt : std::optional<std::uint16_t>(corners);
  update_bumpers();
}

void RflexEmulator::advance(Duration now) {
  while (next_report_ <= now) {
    move_to(next_report_);
    report_burst();
    const bool periodic = reporting_motion() || sonar_on_ || ir_on_;
    next_report_ = periodic ? next_report_ + (reporting_motion() ? motion_period_ : kSensorPeriod) : Duration::max();
  }
  move_to(now);
}

void RflexEmulator::report_burst() {
  const RflexModel& model = options_.model;
  if (reporting_motion()) {
    const auto moving = [&](int axis) { return braked_ ? std::int64_t{0} : velocity_[axis]; };
    if ((axis_mask_ & 1U) != 0) {
      send(hw::motion_report({timestamp(), hw::kTranslationAxis, distance_counter(),
                              static_cast<std::int32_t>(moving(0))}, 0));
    }
    if ((axis_mask_ & 2U) != 0) {
      send(hw::motion_report({timestamp(), hw::kRotationAxis, bearing_counter(), static_cast<std::int32_t>(moving(1))},
                             0));
    }
  }
  const geometry::Pose2 pose = drive_.true_pose();
  if (sonar_on_ && sonar_ring_.size() > 0) {
    std::vector<hw::SonarEcho> echoes;
    for (int i = 0; i < sonar_ring_.size(); ++i) {
      const double metres = sonar_ring_.range(i, options_.map, pose, options_.sonar_max_range);
      const double units = std::min(65535.0, metres * 1000.0 * model.range_distance_conversion);
      echoes.push_back({sonar_ids_[static_cast<std::size_t>(i)], static_cast<std::uint16_t>(units)});
    }
    send(hw::sonar_report(timestamp(), echoes, 0));
  }
  if (ir_on_ && model.ir_banks > 0) {
    std::vector<hw::IrBank> banks(static_cast<std::size_t>(model.ir_banks));
    for (int i = 0; i < ir_ring_.size(); ++i) {
      const double millimetres = ir_ring_.range(i, options_.map, pose, options_.ir_max_range) * 1000.0;
      // 4 mm per count: `rflex_ir_calib [4 1 ...]` reads it back.
      banks[static_cast<std::size_t>(i / 8)][static_cast<std::size_t>(i % 8)] =
          static_cast<std::uint8_t>(std::clamp(millimetres / 4.0, 0.0, 255.0));
    }
    send(hw::ir_report(timestamp(), banks, 0));
  }
}

Duration RflexEmulator::next_deadline() const {
  Duration due = next_report_;
  if (options_.failsafe > 0.0 && (velocity_[0] != 0 || velocity_[1] != 0)) {
    due = std::min(due, last_velocity_command_ + std::chrono::duration_cast<Duration>(
                                                     std::chrono::duration<double>(options_.failsafe)) + 1ms);
  }
  return due;
}

std::vector<Telegram> RflexEmulator::take_output() { return std::exchange(output_, {}); }

std::string RflexEmulator::describe() const {
  std::ostringstream out;
  out << "RFLEX " << options_.model.name << (braked_ ? ", braked" : "")
      << (reporting_motion() ? ", reporting" : ", silent") << (sonar_on_ ? ", sonar on" : "")
      << (ir_on_ ? ", IR on" : "");
  // The true pose, what a driver's odometry is checked against (docs/reference-checks).
  const geometry::Pose2& pose = drive_.true_pose();
  char where[80];
  std::snprintf(where, sizeof where, ", at (%.2f, %.2f, %.0f deg)", pose.x, pose.y, pose.yaw * 180.0 / std::numbers::pi);
  out << where;
  return out.str();
}

}  // namespace playerkit::emulators::rflex
