#include "families/p2os/emulator/p2os_robot_emulator.hpp"

#include "families/p2os/emulator/sip_units.hpp"
#include "families/p2os/protocol/aux_serial.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/gyro_packet.hpp"
#include "families/p2os/protocol/packet_types.hpp"
#include "families/p2os/protocol/sync.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

namespace playerkit::emulators {
namespace {

namespace hw = hardware::p2os;
namespace command = hardware::p2os::command;
using std::chrono::duration_cast;
using Seconds = std::chrono::duration<double>;

// A frame left incomplete this long is taken for noise: one byte is dropped
// and the hunt resumes, so a stray FA FB with a large length cannot hold up
// the host's next packets. At 9600 baud the largest frame takes 0.21 s.
constexpr Duration kStaleInputTimeout = std::chrono::milliseconds(500);

// The driver drops odometry steps over 100 mm per SIP (p2os.md §5 quirk 5).
constexpr double kMaxStepPerSip = 0.099;  // metres

// Gyro rate units per deg/s when the row gives no GyroScaler.
constexpr double kDefaultGyroScaler = 1.626;
constexpr std::uint8_t kGyroTemperature = 25;

double seconds(Duration d) { return duration_cast<Seconds>(d).count(); }
constexpr double kDegree = std::numbers::pi / 180.0;

const hw::RobotParams& row_for(const P2osEmulatorOptions& options) {
  const hw::RobotParams* row = hw::find_robot_params("Pioneer", options.subclass);
  if (row == nullptr) {
    throw std::invalid_argument("p2os emulator: subclass \"" + options.subclass +
                                "\" is not a row of the robot parameter table (e.g. p3dx, "
                                "p2dx, p3at, amigo, perfpb, pion1m)");
  }
  return *row;
}

P2osEmulatorOptions validated(P2osEmulatorOptions options) {
  auto fail = [](const std::string& what) { throw std::invalid_argument("p2os emulator: " + what); };
  if (options.robot_name.size() > hw::kMaxSyncStringLength ||
      options.robot_name.find('\0') != std::string::npos) {
    fail("robot name \"" + options.robot_name + "\" must be at most 19 characters without NUL");
  }
  if (options.sip_period <= Duration::zero()) fail("the SIP period must be positive");
  if (options.motion_step <= Duration::zero()) fail("the motion step must be positive");
  if (options.watchdog && *options.watchdog <= Duration::zero()) fail("the watchdog must be positive");
  if (options.gripper_travel_time <= Duration::zero()) fail("the gripper travel time must be positive");
  if (!(options.sonar_max_range > 0.0)) fail("the sonar range must be positive");
  if (options.sonars_per_sip < 0) fail("sonars per SIP must be 0 (all) or more");
  if (options.footprint_radius && !(*options.footprint_radius > 0.0)) {
    fail("the footprint radius must be positive");
  }
  if (!std::isfinite(options.battery_volts)) fail("the battery voltage must be finite");
  if (options.cmucam_blob) {
    try {
      hw::encode_cmucam_tracking(*options.cmucam_blob);
    } catch (const hw::EncodeError& e) {
      fail(e.what());
    }
  }
  return options;
}

mobile_base::DriveGeometry geometry_for(const hw::RobotParams& row, const P2osEmulatorOptions& options) {
  return {.wheelbase = row.wheelbase() / 1000.0,
          .footprint_radius = options.footprint_radius.value_or(row.radius / 1000.0),
          .max_speed = std::min(row.max_velocity / 1000.0, kMaxStepPerSip / seconds(options.sip_period)),
          .max_turn_rate = row.max_rot_velocity * kDegree};
}

std::optional<int> integer_argument(const hw::Command& c) {
  if (c.form != hw::ArgumentForm::integer) return std::nullopt;
  return c.value();
}

// Bumper switch for an obstacle at `bearing` (robot frame): five switches
// per side, switch 1 the leftmost seen from the robot looking out over it.
void press_bumper(double bearing, std::uint8_t& front, std::uint8_t& rear) {
  const double sector = std::numbers::pi / 5.0;
  const bool at_front = std::abs(bearing) <= std::numbers::pi / 2.0;
  const double outward = at_front ? bearing : geometry::normalize_angle(bearing - std::numbers::pi);
  const int k = std::clamp(static_cast<int>(std::floor((std::numbers::pi / 2.0 - outward) / sector)), 0, 4);
  (at_front ? front : rear) |= static_cast<std::uint8_t>(1u << k);
}

}  // namespace

P2osRobotEmulator::P2osRobotEmulator(P2osEmulatorOptions options)
    : options_(validated(std::move(options))),
      params_(row_for(options_)),
      drive_(geometry_for(params_, options_), options_.odometry_error, options_.map,
             options_.initial_pose),
      gripper_(seconds(options_.gripper_travel_time)),
      sonar_(params_) {}

// ---- time -----------------------------------------------------------------

std::optional<Duration> P2osRobotEmulator::watchdog_deadline() const {
  if (!connected() || !options_.watchdog || watchdog_tripped_ || !drive_.commanded_to_move()) {
    return std::nullopt;
  }
  return last_packet_ + *options_.watchdog;
}

std::optional<Duration> P2osRobotEmulator::stale_input_deadline() const {
  if (!input_waiting_since_) return std::nullopt;
  return *input_waiting_since_ + kStaleInputTimeout;
}

Duration P2osRobotEmulator::next_deadline() const {
  Duration next = Duration::max();
  if (connected()) next = std::min(next, next_sip_);
  if (const auto watchdog = watchdog_deadline()) next = std::min(next, *watchdog);
  if (const auto stale = stale_input_deadline()) next = std::min(next, *stale);
  return next;
}

void P2osRobotEmulator::integrate_to(Duration t) {
  if (t <= integrated_until_) return;
  const double elapsed = seconds(t - integrated_until_);
  drive_.run(elapsed, seconds(options_.motion_step));
  gripper_.run(elapsed);
  integrated_until_ = t;
}

void P2osRobotEmulator::advance(Duration now) {
  now = std::max(now, now_);
  for (;;) {
    const Duration next = next_deadline();
    if (next > now) break;
    integrate_to(next);
    now_ = next;
    if (const auto watchdog = watchdog_deadline(); watchdog && *watchdog <= next) {
      // P2OS stops a robot whose host fell silent; it moves again on the
      // next velocity command.
      translation_setpoint_ = rotation_setpoint_ = 0;
      drive_.stop();
      watchdog_tripped_ = true;
    }
    if (const auto stale = stale_input_deadline(); stale && *stale <= next) {
      input_waiting_since_.reset();
      if (!input_.empty()) {
        input_.erase(input_.begin());
        ++counters_.noise_bytes;
        parse_input(next);
      }
    }
    if (connected() && next_sip_ <= next) {
      if (gyro_on_) send_gyro_packet();
      send_sip();
      next_sip_ += options_.sip_period;
    }
  }
  integrate_to(now);
  now_ = now;
}

// ---- bytes in -------------------------------------------------------------

void P2osRobotEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) {
  advance(now);
  if (bytes.empty()) return;
  if (options_.model_baud != 0 && host_baud != 0 && host_baud != options_.model_baud) {
    // At the wrong speed the UART sees garbage, which also spoils any frame
    // that was arriving.
    counters_.noise_bytes += bytes.size() + input_.size();
    input_.clear();
    input_waiting_since_.reset();
    return;
  }
  input_.insert(input_.end(), bytes.begin(), bytes.end());
  parse_input(now_);
}

void P2osRobotEmulator::parse_input(Duration now) {
  // Every pass consumes at least one byte or returns.
  while (!input_.empty()) {
    const framing::FrameScan scan = format_.scan(input_);
    const auto consumed = static_cast<std::ptrdiff_t>(scan.length);
    switch (scan.kind) {
      case framing::FrameScan::Kind::need_more:
        if (!input_waiting_since_) input_waiting_since_ = now;
        return;
      case framing::FrameScan::Kind::frame: {
        ++counters_.frames;
        const std::vector<std::uint8_t> frame(input_.begin(), input_.begin() + consumed);
        input_.erase(input_.begin(), input_.begin() + consumed);
        input_waiting_since_.reset();
        handle_frame(hw::frame_payload(frame), now);
        break;
      }
      case framing::FrameScan::Kind::bad_checksum:
        // Drop only the FA: a frame hidden behind a corrupt header is found.
        ++counters_.bad_checksums;
        input_.erase(input_.begin());
        input_waiting_since_.reset();
        break;
      case framing::FrameScan::Kind::skip:
        counters_.noise_bytes += scan.length;
        input_.erase(input_.begin(), input_.begin() + consumed);
        input_waiting_since_.reset();
        break;
    }
  }
  input_waiting_since_.reset();
}

void P2osRobotEmulator::handle_frame(std::span<const std::uint8_t> payload, Duration now) {
  hw::Command c;
  try {
    c = hw::decode_command(payload);
  } catch (const hw::DecodeError&) {
    ++counters_.undecodable;
    return;
  }
  ++received_[c.number];
  if (connected()) {
    last_packet_ = now;
    watchdog_tripped_ = false;
    handle_connected(c);
  } else {
    handle_handshake(c, now);
  }
}

void P2osRobotEmulator::handle_handshake(const hw::Command& c, Duration now) {
  switch (c.number) {
    case command::sync0:
      send({hw::packet_type::sync0});
      state_ = P2osLinkState::got_sync0;
      return;
    case command::sync1:  // also OPEN
      if (state_ == P2osLinkState::got_sync0) {
        send({hw::packet_type::sync1});
        state_ = P2osLinkState::got_sync1;
      } else if (state_ == P2osLinkState::synced) {
        open(now);
      } else {
        ++counters_.ignored;
      }
      return;
    case command::sync2:  // also CLOSE
      if (state_ == P2osLinkState::got_sync1 || state_ == P2osLinkState::synced) {
        send(hw::encode_sync2_reply({options_.robot_name, std::string(params_.robot_class),
                                     std::string(params_.subclass)}));
        state_ = P2osLinkState::synced;
      } else {
        state_ = P2osLinkState::unconnected;
      }
      return;
    default:
      // A controller that is not connected listens for the handshake only.
      ++counters_.ignored;
      return;
  }
}

void P2osRobotEmulator::open(Duration now) {
  state_ = P2osLinkState::connected;
  motors_enabled_ = false;
  sonar_on_ = options_.sonar_on_at_open;
  gyro_on_ = false;
  velocity_mode_ = VelocityMode::translate_rotate;
  translation_setpoint_ = rotation_setpoint_ = 0;
  drive_.stop();
  drive_.reset_odometry();
  drive_.take_contact();
  next_sonar_ = 0;
  last_packet_ = now;
  watchdog_tripped_ = false;
  next_sip_ = now + options_.sip_period;
}

void P2osRobotEmulator::close() {
  state_ = P2osLinkState::unconnected;
  motors_enabled_ = false;
  gyro_on_ = false;
  translation_setpoint_ = rotation_setpoint_ = 0;
  drive_.stop();
}

void P2osRobotEmulator::host_disconnected(Duration now) {
  advance(now);
  // A hang-up ends an open session, as CLOSE does (§6.4). A handshake in
  // progress is left alone: the runner may learn of the old host's hang-up
  // only after the bytes of a host that came back (its CLOSE and the new
  // SYNC0 in one read), and wiping the SYNC0 would leave that host
  // unanswered. A real controller never sees the port close at all, and
  // SYNC0 restarts a stale handshake anyway (§6.3).
  if (!connected()) return;
  close();
  input_.clear();
  input_waiting_since_.reset();
}

void P2osRobotEmulator::apply_velocity_setpoints() {
  drive_.command(translation_setpoint_ / 1000.0, rotation_setpoint_ * kDegree);
}

void P2osRobotEmulator::handle_connected(const hw::Command& c) {
  const std::optional<int> argument = integer_argument(c);
  const bool drive_command = c.number == command::vel || c.number == command::rvel ||
                             c.number == command::vel2;
  if (drive_command && (!motors_enabled_ || !argument)) {
    ++counters_.ignored;  // disabled motors ignore velocities
    return;
  }
  switch (c.number) {
    case command::pulse:
    case command::open:
    case command::joydrive:
    case command::sound:
    case command::playlist:
    case command::gripper_value:
    case command::tty3:
    case command::setv:
      return;  // accepted; nothing to emulate
    case command::close:
      close();
      return;
    case command::enable:
      if (!argument) break;
      motors_enabled_ = *argument != 0;
      if (!motors_enabled_) {
        translation_setpoint_ = rotation_setpoint_ = 0;
        drive_.stop();
      }
      return;
    case command::seto:
      drive_.reset_odometry();
      return;
    case command::vel:
      if (velocity_mode_ == VelocityMode::wheels) rotation_setpoint_ = 0;
      velocity_mode_ = VelocityMode::translate_rotate;
      translation_setpoint_ = *argument;
      apply_velocity_setpoints();
      return;
    case command::rvel:
      if (velocity_mode_ == VelocityMode::wheels) translation_setpoint_ = 0;
      velocity_mode_ = VelocityMode::translate_rotate;
      rotation_setpoint_ = *argument;
      apply_velocity_setpoints();
      return;
    case command::vel2: {
      velocity_mode_ = VelocityMode::wheels;
      const hw::Vel2Wheels wheels = hw::decode_vel2(c.magnitude);
      const double unit = params_.vel2_divisor / 1000.0;
      drive_.command_wheels({wheels.left * unit, wheels.right * unit});
      return;
    }
    case command::stop:
      translation_setpoint_ = rotation_setpoint_ = 0;
      drive_.stop();
      return;
    case command::sonar:
      if (!argument) break;
      sonar_on_ = *argument != 0;
      return;
    case command::gripper:
      if (!argument || !options_.has_gripper) break;
      gripper_.command(*argument);
      return;
    case command::gyro:
      if (!argument) break;
      gyro_on_ = *argument != 0;
      return;
    case command::getaux2:
      if (!argument || !options_.has_cmucam) break;
      if (*argument > 0) send_cmucam(*argument);  // GETAUX2 0 only flushes
      return;
    default:
      break;
  }
  ++counters_.ignored;
}

// ---- packets out ----------------------------------------------------------

void P2osRobotEmulator::send(std::vector<std::uint8_t> payload) {
  output_.push_back(Telegram{hw::build_frame(payload), true});
}

std::vector<Telegram> P2osRobotEmulator::take_output() {
  std::vector<Telegram> out;
  out.swap(output_);
  return out;
}

hw::StandardSip P2osRobotEmulator::build_sip() {
  hw::StandardSip sip;
  const geometry::Pose2& odometry = drive_.odometry();
  const mobile_base::WheelVelocities wheels = drive_.wheels();
  sip.x_position = p2os::position_units(odometry.x, params_);
  sip.y_position = p2os::position_units(odometry.y, params_);
  sip.heading = p2os::heading_units(odometry.yaw, params_);
  sip.left_velocity = p2os::velocity_units(wheels.left, params_);
  sip.right_velocity = p2os::velocity_units(wheels.right, params_);
  sip.status = wheels.left != 0.0 || wheels.right != 0.0 ? hw::packet_type::sip_moving
                                                         : hw::packet_type::sip_stopped;
  sip.battery = static_cast<std::uint8_t>(std::clamp(std::lround(options_.battery_volts * 10.0), 0L, 255L));

  std::uint8_t front = 0, rear = 0;
  const mobile_base::Contact contact = drive_.take_contact();
  const bool has_bumpers = params_.extra && params_.extra->num_front_bumpers > 0;
  if (contact.stalled && has_bumpers) press_bumper(contact.bearing, front, rear);
  sip.stall_bumpers_low = hw::stall_bumper_byte(contact.stalled, rear);
  sip.stall_bumpers_high = hw::stall_bumper_byte(contact.stalled, front);

  sip.control = static_cast<std::uint16_t>(sip.heading);
  sip.flags = motors_enabled_ ? hw::kSipFlagMotorsEnabled : 0;
  const int count = sonar_.size();
  if (sonar_on_ && count > 0) {
    const int arrays = std::min(4, (count + 7) / 8);
    sip.flags = static_cast<std::uint16_t>(sip.flags | (((1u << arrays) - 1u) << 1));
    const int per_sip = options_.sonars_per_sip > 0 ? std::min(options_.sonars_per_sip, count) : count;
    for (int k = 0; k < per_sip; ++k) {
      const int index = (next_sonar_ + k) % count;
      sip.sonar.push_back({static_cast<std::uint8_t>(index),
                           p2os::range_units(sonar_range(index), params_)});
    }
    next_sonar_ = (next_sonar_ + per_sip) % count;
  }
  sip.compass = hw::compass_byte(drive_.true_pose().yaw / kDegree);
  sip.analog_port = options_.analog_port;
  sip.gripper_state = options_.has_gripper ? gripper_.state_bits() : 0;
  sip.analog = options_.analog_input;
  sip.digital_in = options_.has_gripper
                       ? static_cast<std::uint8_t>(gripper_.beam_bits() | (options_.digital_inputs & 0xC0))
                       : options_.digital_inputs;
  return sip;
}

void P2osRobotEmulator::send_sip() {
  send(hw::encode_sip(build_sip()));
  ++counters_.sips_sent;
}

void P2osRobotEmulator::send_gyro_packet() {
  const mobile_base::WheelVelocities wheels = drive_.wheels();
  const double turn_rate = (wheels.right - wheels.left) / (params_.wheelbase() / 1000.0);
  const double scaler = params_.extra && params_.extra->gyro_scaler > 0.0
                            ? params_.extra->gyro_scaler
                            : kDefaultGyroScaler;
  // Below 512 is counter-clockwise (p2os.md §2.6).
  const double raw = std::round(hw::kGyroRateAtRest - turn_rate / kDegree / scaler);
  const auto rate = static_cast<std::uint16_t>(std::clamp(raw, 0.0, double{hw::kGyroRateMax}));
  send(hw::encode_gyro_packet({{{rate, kGyroTemperature}}}));
}

void P2osRobotEmulator::send_cmucam(int byte_count) {
  const auto message = hw::encode_cmucam_tracking(options_.cmucam_blob.value_or(hw::CmucamTracking{}));
  const auto size = static_cast<std::size_t>(std::min<int>(byte_count, static_cast<int>(message.size())));
  send(hw::encode_aux_serial({hw::packet_type::serial_aux2, {message.begin(), message.begin() + static_cast<std::ptrdiff_t>(size)}}));
}

// ---- accessors ------------------------------------------------------------

void P2osRobotEmulator::set_true_pose(const geometry::Pose2& pose) {
  integrate_to(now_);
  drive_.set_true_pose(pose);
}

double P2osRobotEmulator::sonar_range(int index) const {
  return sonar_.range(index, options_.map, drive_.true_pose(), options_.sonar_max_range);
}

std::string P2osRobotEmulator::describe() const {
  std::string text = std::string(params_.robot_class) + " " + std::string(params_.subclass) +
                     " \"" + options_.robot_name + "\", ";
  // Where the robot truly is, as every robot emulator says it: what a
  // driver's odometry and a navigation run are checked against.
  const geometry::Pose2 pose = drive_.true_pose();
  char where[64];
  std::snprintf(where, sizeof where, ", at (%.2f, %.2f, %.0f deg)", pose.x, pose.y, pose.yaw * 180.0 / std::numbers::pi);
  switch (state_) {
    case P2osLinkState::unconnected: return text + "waiting for SYNC0" + where;
    case P2osLinkState::got_sync0: return text + "handshake: SYNC0 echoed" + where;
    case P2osLinkState::got_sync1: return text + "handshake: SYNC1 echoed" + where;
    case P2osLinkState::synced: return text + "synchronised, waiting for OPEN" + where;
    case P2osLinkState::connected: break;
  }
  const auto period_ms = std::chrono::duration_cast<std::chrono::milliseconds>(options_.sip_period).count();
  return text + "connected, motors " + (motors_enabled_ ? "enabled" : "disabled") + ", sonar " +
         (sonar_on_ ? "on" : "off") + ", a SIP every " + std::to_string(period_ms) + " ms" + where;
}

}  // namespace playerkit::emulators
