#include "families/nomad/emulator/nomad_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/ray_cast.hpp"

namespace playerkit::emulators {

namespace {

namespace nomad = hardware::nomad;
namespace type = hardware::nomad::message_type;
using namespace std::chrono_literals;

constexpr double kMetresPerTenthInch = 0.00254;
constexpr double kRadiansPerTenthDegree = std::numbers::pi / 1800.0;
constexpr double kMetresPerInch = 0.0254;
constexpr int kSonarMaxInches = 255;
constexpr double kSensorSpacing = 2.0 * std::numbers::pi / 16.0;
// Motion is integrated in steps no longer than this, so that a wall is met
// before the body passes through it.
constexpr double kLongestStep = 0.01;

double seconds(Duration duration) { return std::chrono::duration<double>(duration).count(); }

// Angles as the robot reports them: tenths of a degree in [0, 3600).
std::int32_t reported_angle(double tenths) {
  const double wrapped = std::fmod(std::fmod(tenths, 3600.0) + 3600.0, 3600.0);
  return static_cast<std::int32_t>(std::lround(wrapped)) % 3600;
}

}  // namespace

NomadEmulator::NomadEmulator(NomadEmulatorOptions options)
    : options_(options),
      ring_(mobile_base::evenly_spaced_ring(static_cast<int>(nomad::kSonarCount), options.sensor_ring_radius, 0.0,
                                            mobile_base::RingOrder::counter_clockwise)),
      noise_(options.odometry_error.seed),
      true_pose_(options.start_pose),
      true_turret_(options.start_pose.yaw) {}

void NomadEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);
  input_.insert(input_.end(), bytes.begin(), bytes.end());
  const nomad::NclientFormat format;
  for (;;) {
    const auto scan = format.scan(input_);
    if (scan.kind == framing::FrameScan::Kind::need_more) break;
    const auto end = input_.begin() + static_cast<std::ptrdiff_t>(scan.length);
    if (scan.kind == framing::FrameScan::Kind::frame) {
      if (const auto request = nomad::decode(std::span(input_).first(scan.length))) handle(*request, now);
    }
    input_.erase(input_.begin(), end);
  }
}

void NomadEmulator::handle(const nomad::Message& request, Duration now) {
  ++requests_;
  if (request.type >= 0 && static_cast<std::size_t>(request.type) < requests_by_type_.size()) {
    ++requests_by_type_[static_cast<std::size_t>(request.type)];
  }
  const auto word = [&request](std::size_t i) { return i < request.words.size() ? request.words[i] : 0; };
  switch (request.type) {
    case type::kConnectRobot:
      connected_ = true;
      pending_.push_back(
          {now + options_.reply_delay, nomad::Message{type::kConnectRobot, {options_.robot_server_port}}});
      send_due_replies();
      return;
    case type::kVelocityMode:
      translation_velocity_ = word(0);
      steering_velocity_ = word(1);
      turret_velocity_ = word(2);
      last_velocity_command_ = now;
      break;
    case type::kZero:
      stop_motion();
      odometry_x_ = odometry_y_ = odometry_steering_ = odometry_turret_ = 0.0;
      break;
    case type::kCommandTimeout:
      command_timeout_ = std::chrono::seconds(std::max(word(0), 0));
      last_velocity_command_ = now;
      break;
    case type::kAccelerations:
      accelerations_ = {word(0), word(1), word(2)};
      break;
    case type::kSpeeds:
      speeds_ = {word(0), word(1), word(2)};
      break;
    default:  // GS, CT and the rest: the state is the answer
      break;
  }
  // The state as it is when the reply leaves, as the server reads it then.
  pending_.push_back({now + options_.reply_delay, std::nullopt});
  send_due_replies();
}

void NomadEmulator::advance(Duration now) {
  send_due_replies();
  while (now_ < now) {
    Duration until = now;
    if (!pending_.empty()) until = std::min(until, std::max(pending_.front().due, now_));
    if (command_timeout_ > 0s && (translation_velocity_ != 0 || steering_velocity_ != 0 || turret_velocity_ != 0)) {
      until = std::min(until, std::max(last_velocity_command_ + command_timeout_, now_));
    }
    move(seconds(until - now_));
    now_ = until;
    if (command_timeout_ > 0s && now_ >= last_velocity_command_ + command_timeout_) stop_motion();
    send_due_replies();
  }
}

void NomadEmulator::send_due_replies() {
  while (!pending_.empty() && pending_.front().due <= now_) {
    const auto& owed = pending_.front().reply;
    output_.push_back({nomad::encode(owed ? *owed : nomad::state_reply(state())), false});
    pending_.pop_front();
  }
}

Duration NomadEmulator::next_deadline() const {
  Duration next = Duration::max();
  if (!pending_.empty()) next = pending_.front().due;
  const bool moving = translation_velocity_ != 0 || steering_velocity_ != 0 || turret_velocity_ != 0;
  if (moving && command_timeout_ > 0s) next = std::min(next, last_velocity_command_ + command_timeout_);
  return next;
}

std::vector<Telegram> NomadEmulator::take_output() { return std::exchange(output_, {}); }

void NomadEmulator::host_disconnected(Duration now) {
  advance(now);
  // The server drops what it owed the client that left; the robot keeps
  // moving until its command timeout stops it, as a real one does.
  pending_.clear();
  input_.clear();
  connected_ = false;
}

void NomadEmulator::stop_motion() { translation_velocity_ = steering_velocity_ = turret_velocity_ = 0; }

void NomadEmulator::move(double duration) {
  while (duration > 0) {
    const double dt = std::min(duration, kLongestStep);
    duration -= dt;
    const double speed = translation_velocity_ * kMetresPerTenthInch;  // m/s
    const double steer_rate = steering_velocity_ * kRadiansPerTenthDegree;
    const double turret_rate = turret_velocity_ * kRadiansPerTenthDegree;

    geometry::Pose2 next = true_pose_;
    next.x += speed * std::cos(true_pose_.yaw) * dt;
    next.y += speed * std::sin(true_pose_.yaw) * dt;
    std::int32_t bumpers = 0;
    const bool blocked = speed != 0 && touches_wall(next, bumpers) && [&] {
      // Only a wall on the side it travels to stops it: it may back away.
      const int ahead = speed > 0 ? 0 : 8;
      for (int k = -3; k <= 3; ++k) {
        if (bumpers & (1 << ((ahead + k + 16) % 16))) return true;
      }
      return false;
    }();
    bumpers_ = bumpers;
    const double travelled = blocked ? 0.0 : speed * dt;
    if (!blocked) {
      true_pose_.x = next.x;
      true_pose_.y = next.y;
    }
    // The encoders' view: scaled, drifting and noisy as configured.
    const auto& error = options_.odometry_error;
    const double distance = std::abs(travelled);
    std::normal_distribution<double> unit_normal;
    double measured = travelled * (1.0 + error.translation_scale);
    double heading_error = error.heading_drift_per_metre * distance;
    if (distance > 0 && error.translation_noise > 0) measured += error.translation_noise * std::sqrt(distance) * unit_normal(noise_);
    if (distance > 0 && error.rotation_noise > 0) heading_error += error.rotation_noise * std::sqrt(distance) * unit_normal(noise_);
    const double odometry_heading = odometry_steering_ * kRadiansPerTenthDegree;
    odometry_x_ += measured / kMetresPerTenthInch * std::cos(odometry_heading);
    odometry_y_ += measured / kMetresPerTenthInch * std::sin(odometry_heading);
    true_pose_.yaw = geometry::normalize_angle(true_pose_.yaw + steer_rate * dt);
    true_turret_ = geometry::normalize_angle(true_turret_ + turret_rate * dt);
    const double rotation_factor = 1.0 + error.rotation_scale;
    odometry_steering_ += steering_velocity_ * dt * rotation_factor + heading_error / kRadiansPerTenthDegree;
    odometry_turret_ += turret_velocity_ * dt * rotation_factor + heading_error / kRadiansPerTenthDegree;
  }
}

bool NomadEmulator::touches_wall(const geometry::Pose2& pose, std::int32_t& bumpers) const {
  bumpers = 0;
  if (options_.map == nullptr) return false;
  for (int k = 0; k < 16; ++k) {
    const double range = grid::cast_ray(*options_.map, pose.translation(), pose.yaw + k * kSensorSpacing,
                                        options_.body_radius, grid::RayStop::occupied);
    if (range < options_.body_radius) bumpers |= 1 << k;
  }
  return bumpers != 0;
}

void NomadEmulator::sense(nomad::RobotState& state) const {
  // The ring turns with the turret, about the body's centre.
  const geometry::Pose2 turret{true_pose_.x, true_pose_.y, true_turret_};
  const auto inches = [&](int index, int max_inches) {
    const double range = ring_.range(index, options_.map, turret, max_inches * kMetresPerInch);
    return std::clamp(static_cast<int>(std::lround(range / kMetresPerInch)), 0, max_inches);
  };
  for (std::size_t i = 0; i < nomad::kSonarCount; ++i) {
    state.sonar[i] = inches(static_cast<int>(i), kSonarMaxInches);
    state.ir[i] = inches(static_cast<int>(i), options_.ir_range_inches);
  }
}

nomad::RobotState NomadEmulator::state() const {
  nomad::RobotState state;
  state.simulation_speed = 1;
  sense(state);
  state.bumpers = bumpers_;
  state.x = static_cast<std::int32_t>(std::lround(odometry_x_));
  state.y = static_cast<std::int32_t>(std::lround(odometry_y_));
  state.steering = reported_angle(odometry_steering_);
  state.turret = reported_angle(odometry_turret_);
  state.translation_velocity = translation_velocity_;
  state.steering_velocity = steering_velocity_;
  state.turret_velocity = turret_velocity_;
  state.motor_status = translation_velocity_ != 0 || steering_velocity_ != 0 || turret_velocity_ != 0 ? 1 : 0;
  state.compass = reported_angle(true_turret_ / kRadiansPerTenthDegree);
  state.controller_time = static_cast<std::int32_t>(std::chrono::duration_cast<std::chrono::milliseconds>(now_).count() / 10);
  state.cpu_voltage = 130;
  state.motor_voltage = 125;
  return state;
}

std::uint64_t NomadEmulator::requests_of(std::int16_t request_type) const {
  if (request_type < 0 || static_cast<std::size_t>(request_type) >= requests_by_type_.size()) return 0;
  return requests_by_type_[static_cast<std::size_t>(request_type)];
}

std::string NomadEmulator::describe() const {
  std::ostringstream text;
  text << "Nomad 200, " << (connected_ ? "connected" : "waiting for CONNECT_ROBOT") << ", " << requests_
       << " requests, at (" << true_pose_.x << ", " << true_pose_.y << ") m";
  return text.str();
}

}  // namespace playerkit::emulators
