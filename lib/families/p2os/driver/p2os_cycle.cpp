// The I/O thread's work between packets: subscription edges, requests,
// commands, the once-per-SIP keep-alive and publishing. Everything here runs
// on the I/O thread with views_mutex_ held.
#include <algorithm>

#include "families/p2os/driver/cmucam_commands.hpp"
#include "families/p2os/driver/p2os_connection.hpp"
#include "families/p2os/protocol/gripper.hpp"
#include "links/link_error.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/errors.hpp"
#include "protocol/messages/gripper.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sound.hpp"

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;
using namespace std::chrono_literals;

namespace {

// The CMUcam needs this long after RS before it tracks (1.5 slept 1 s).
constexpr auto kCmucamResetTime = 1s;
// A CMUcam poll that got no SERAUX2 back is repeated after this long.
constexpr auto kCmucamPollRetry = 1s;

}  // namespace

bool P2osConnection::send(const hw::Command& command) {
  if (link_error_) return false;
  try {
    send_command(link(), command);
  } catch (const links::LinkError& e) {
    link_error_ = e.what();
    return false;
  }
  packet_sent_this_cycle_ = true;
  return true;
}

bool P2osConnection::send_all(const std::vector<hw::Command>& commands) {
  return std::all_of(commands.begin(), commands.end(), [this](const hw::Command& c) { return send(c); });
}

int P2osConnection::count_views(P2osRole role) const {
  return static_cast<int>(
      std::count_if(views_.begin(), views_.end(), [role](const View& view) { return view.role == role; }));
}

void P2osConnection::serve_views(std::chrono::steady_clock::time_point now) {
  reconcile_subscriptions(now);
  serve_requests();
  take_commands();
  if (new_sip_) {
    end_of_cycle(now);
    publish();
    new_sip_ = false;
  }
}

void P2osConnection::reconcile_subscriptions(std::chrono::steady_clock::time_point now) {
  // position: the first device disables the motors and zeroes the odometry
  // (as 1.5); the last one stops the robot and disables them.
  const bool position_now = count_views(P2osRole::position) > 0;
  if (position_now && !position_active_) {
    position_active_ = true;
    motors_wanted_ = false;
    velocity_ = {};
    velocity_mode_ = VelocityMode::direct_wheel;
    send(hw::Command::with_integer(hw::command::enable, 0));
    motors_sent_ = false;
    if (send(hw::Command::type_only(hw::command::seto))) odometry_.robot_reset_sent();
  } else if (!position_now && position_active_) {
    position_active_ = false;
    motors_wanted_ = false;
    velocity_ = {};
    send_motor_command();
    send(hw::Command::with_integer(hw::command::enable, 0));
    motors_sent_ = false;
  }
  // After a reconnect the robot starts with its motors off: switch them back
  // on if a client had.
  const bool motors = position_active_ && motors_wanted_;
  if (motors != motors_sent_ && send(hw::Command::with_integer(hw::command::enable, motors ? 1 : 0))) {
    motors_sent_ = motors;
  }

  // sonar: on with the first device, off after the last; POWER in between.
  const int sonars = count_views(P2osRole::sonar);
  if (sonars > 0 && sonar_views_ == 0) sonar_wanted_ = true;
  if (sonars == 0 && sonar_views_ > 0) sonar_wanted_ = false;
  sonar_views_ = sonars;
  if (sonar_sent_ != sonar_wanted_ &&
      send(hw::Command::with_integer(hw::command::sonar, sonar_wanted_ ? 1 : 0))) {
    sonar_sent_ = sonar_wanted_;
  }

  // gyro: GYROPACs only while a p2os_gyro device wants them.
  const bool gyro = count_views(P2osRole::gyro) > 0;
  if (gyro != gyro_sent_ && send(hw::Command::with_integer(hw::command::gyro, gyro ? 1 : 0))) {
    gyro_sent_ = gyro;
  }

  // CMUcam: reset when the first p2os_cmucam device comes, track a second
  // later, stop tracking when the last one leaves.
  const bool camera = count_views(P2osRole::cmucam) > 0;
  if (camera && cmucam_phase_ == CmucamPhase::off) {
    if (send_all(cmucam_reset_commands())) {
      cmucam_phase_ = CmucamPhase::resetting;
      cmucam_track_at_ = now + kCmucamResetTime;
    }
  } else if (camera && cmucam_phase_ == CmucamPhase::resetting && now >= cmucam_track_at_) {
    if (send_all(cmucam_track_commands(cmucam_tracking_text_))) {
      cmucam_phase_ = CmucamPhase::tracking;
      cmucam_polled_at_ = now;
      cmucam_answered_ = false;
    }
  } else if (!camera && cmucam_phase_ != CmucamPhase::off) {
    send(cmucam_stop_command());
    cmucam_phase_ = CmucamPhase::off;
  }
}

void P2osConnection::serve_requests() {
  for (const View& view : views_) {
    if (view.device->pending_requests() > 0) view.device->service_requests();
  }
}

void P2osConnection::take_commands() {
  std::optional<VelocityCommand> velocity;
  for (const View& view : views_) {
    switch (view.role) {
      case P2osRole::position:
        if (auto command = view.device->take_command()) {
          try {
            const auto decoded = protocol::decode<protocol::PositionCommand>(command->payload);
            velocity = VelocityCommand{decoded.xspeed, decoded.yawspeed};
            motor_limits_ = view.limits;
          } catch (const protocol::DecodeError&) {
            // The device checked the size; nothing else can be wrong.
          }
        }
        break;
      case P2osRole::gripper:
        if (auto command = view.device->take_command(); command && session_up_) {
          protocol::GripperCommand decoded;
          try {
            decoded = protocol::decode<protocol::GripperCommand>(command->payload);
          } catch (const protocol::DecodeError&) {
            break;
          }
          const std::pair<std::uint8_t, std::uint8_t> pair{decoded.cmd, decoded.arg};
          // As 1.5: a command goes to the robot when it differs from the last one sent.
          if (pair != gripper_sent_ && send(hw::Command::with_integer(hw::command::gripper, decoded.cmd))) {
            gripper_sent_ = pair;
            if (decoded.cmd == hw::gripper_command::press || decoded.cmd == hw::gripper_command::lift_carry) {
              send(hw::Command::with_integer(hw::command::gripper_value, decoded.arg));
            }
          }
        }
        break;
      case P2osRole::sound:
        if (auto command = view.device->take_command(); command && session_up_) {
          protocol::SoundCommand decoded;
          try {
            decoded = protocol::decode<protocol::SoundCommand>(command->payload);
          } catch (const protocol::DecodeError&) {
            break;
          }
          if (decoded.index != 0) send(hw::Command::with_integer(hw::command::sound, decoded.index));
        }
        break;
      default:
        break;
    }
  }
  // While the robot is away commands are dropped: nothing old is replayed.
  if (velocity && session_up_ && position_active_) {
    velocity_ = *velocity;
    send_motor_command();
  }
}

void P2osConnection::send_motor_command() {
  if (send_all(motor_commands(velocity_, velocity_mode_, *params_, motor_limits_))) {
    motor_sent_this_cycle_ = true;
  }
}

void P2osConnection::end_of_cycle(std::chrono::steady_clock::time_point now) {
  // The robot's watchdog wants a packet every cycle: the motor command while
  // someone drives, else PULSE unless something else went.
  if (position_active_ && !motor_sent_this_cycle_) send_motor_command();
  if (!packet_sent_this_cycle_) send(hw::Command::plain(hw::command::pulse));
  if (cmucam_phase_ == CmucamPhase::tracking &&
      (cmucam_answered_ || now - cmucam_polled_at_ >= kCmucamPollRetry)) {
    send_all(cmucam_poll_commands());
    cmucam_polled_at_ = now;
    cmucam_answered_ = false;
  }
  motor_sent_this_cycle_ = false;
  packet_sent_this_cycle_ = false;
}

void P2osConnection::publish() {
  if (views_.empty()) return;
  const core::Timestamp stamp = views_.front().device->clock().now();
  for (const View& view : views_) {
    std::vector<std::uint8_t> payload;
    switch (view.role) {
      case P2osRole::position:
        if (!odometry_.ready()) continue;
        payload = protocol::encode(readings_.position(odometry_.pose()));
        break;
      case P2osRole::sonar: payload = protocol::encode(readings_.sonar()); break;
      case P2osRole::gripper: payload = protocol::encode(readings_.gripper()); break;
      case P2osRole::power: payload = protocol::encode(readings_.power()); break;
      case P2osRole::bumper: payload = protocol::encode(readings_.bumper()); break;
      case P2osRole::aio: payload = protocol::encode(readings_.aio()); break;
      case P2osRole::dio: payload = protocol::encode(readings_.dio()); break;
      case P2osRole::cmucam: payload = protocol::encode(readings_.blobfinder()); break;
      case P2osRole::compass: payload = protocol::encode(readings_.compass()); break;
      case P2osRole::gyro: payload = protocol::encode(readings_.gyro()); break;
      case P2osRole::sound: continue;  // no data
    }
    view.device->publish(std::move(payload), stamp);
  }
}

}  // namespace playerkit::drivers::p2os
