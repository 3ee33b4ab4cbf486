// The I/O thread's work between packets: subscription edges, requests,
// commands, the 100 ms cycle and publishing, all with views_mutex_ held;
// and the devices' requests (rflex.md §3).
#include <algorithm>

#include "families/rflex/driver/rflex_connection.hpp"
#include "families/rflex/driver/rflex_motion.hpp"
#include "families/rflex/protocol/rflex_messages.hpp"
#include "interfaces/position_requests.hpp"
#include "interfaces/ranger_requests.hpp"
#include "links/link_error.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/errors.hpp"

namespace playerkit::drivers::rflex {

namespace hw = hardware::rflex;

bool RflexConnection::send(const hw::Packet& packet) {
  if (link_error_) return false;
  try {
    link().write_all(hw::encode_packet(packet), links::deadline_in(std::chrono::milliseconds(200)));
  } catch (const links::LinkError& e) {
    link_error_ = e.what();
    return false;
  }
  return true;
}

int RflexConnection::count_views(RflexRole role) const {
  return static_cast<int>(std::count_if(views_.begin(), views_.end(), [role](const View& v) { return v.role == role; }));
}

void RflexConnection::reconcile_subscriptions() {
  if (!session_up_) return;
  // position: the first device resets the motion defaults and stops; the
  // last one stops and brakes (as 1.5).
  const bool position_now = count_views(RflexRole::position) > 0;
  if (position_now && !position_active_) {
    position_active_ = true;
    xspeed_ = yawspeed_ = 0.0;
    send(hw::set_defaults());
    send_velocity();
  } else if (!position_now && position_active_) {
    position_active_ = false;
    xspeed_ = yawspeed_ = 0.0;
    send_velocity();
    send(hw::brake_set());
  }

  const int sonars = count_views(RflexRole::sonar);
  if (sonars > 0 && sonar_views_ == 0) sonar_wanted_ = true;
  if (sonars == 0 && sonar_views_ > 0) sonar_wanted_ = false;
  sonar_views_ = sonars;
  if (sonar_sent_ != sonar_wanted_) {
    const hw::SonarRun run{static_cast<std::uint32_t>(settings_.sonar_echo_delay),
                           static_cast<std::uint32_t>(settings_.sonar_ping_delay),
                           static_cast<std::uint32_t>(settings_.sonar_set_delay),
                           sonar_wanted_ ? hw::kSonarRunOn : std::uint8_t{0}};
    if (send(hw::sonar_run(run))) sonar_sent_ = sonar_wanted_;
  }

  const int irs = count_views(RflexRole::ir);
  if (irs > 0 && ir_views_ == 0) ir_wanted_ = true;
  if (irs == 0 && ir_views_ > 0) ir_wanted_ = false;
  ir_views_ = irs;
  if (ir_sent_ != ir_wanted_ && send(hw::ir_run(ir_wanted_))) ir_sent_ = ir_wanted_;
}

void RflexConnection::serve_requests() {
  for (const View& view : views_) {
    if (view.device->pending_requests() > 0) view.device->service_requests();
  }
}

void RflexConnection::take_commands() {
  for (const View& view : views_) {
    if (view.role != RflexRole::position) continue;
    const auto command = view.device->take_command();
    if (!command) continue;
    try {
      const auto decoded = protocol::decode<protocol::PositionCommand>(command->payload);
      if (joystick_holds_ > 0) {
        --joystick_holds_;  // the joystick drove just now (1.5 ignored the next five)
        continue;
      }
      // While the robot is away commands are dropped: nothing old is replayed.
      if (!session_up_ || !position_active_) continue;
      xspeed_ = decoded.xspeed;
      yawspeed_ = decoded.yawspeed;
      send_velocity();
    } catch (const protocol::DecodeError&) {
      // The device checked the size; nothing else can be wrong.
    }
  }
}

void RflexConnection::send_velocity() {
  // Motion waits for the first pair of reports: the odometry counts from
  // there, so a robot that moved before would be off by what it drove.
  const bool may_move = position_active_ && readings_.odometry_ready();
  const auto [translation, rotation] =
      may_move ? velocity_commands(xspeed_, yawspeed_, settings_) : velocity_commands(0, 0, settings_);
  send(hw::axis_set_direction(translation));
  send(hw::axis_set_direction(rotation));
}

void RflexConnection::cycle() {
  if (!session_up_) return;
  // The controller's failsafe stops a robot that hears no velocity: the
  // command (or a stop) goes again every cycle, as in 1.5.
  send_velocity();
  send(hw::system_status_request());
  if (settings_.joystick) send(hw::joystick_request());
}

void RflexConnection::publish() {
  if (views_.empty()) return;
  const core::Timestamp stamp = views_.front().device->clock().now();
  for (const View& view : views_) {
    std::vector<std::uint8_t> payload;
    switch (view.role) {
      case RflexRole::position:
        if (!readings_.odometry_ready()) continue;
        payload = protocol::encode(readings_.position());
        break;
      case RflexRole::sonar: payload = protocol::encode(readings_.sonar()); break;
      case RflexRole::ir: payload = protocol::encode(readings_.ir()); break;
      case RflexRole::bumper: payload = protocol::encode(readings_.bumper()); break;
      case RflexRole::power:
        if (!readings_.status()) continue;
        payload = protocol::encode(readings_.power());
        break;
      // The RFLEX protocol as known gives no analog or general digital
      // inputs: empty data (1.5 published whatever its buffer held).
      case RflexRole::aio: payload = protocol::encode(protocol::AioData{}); break;
      case RflexRole::dio: payload = protocol::encode(protocol::DioData{}); break;
    }
    view.device->publish(std::move(payload), stamp);
  }
}

// ---------------------------------------------------------------- requests

core::RequestResult RflexConnection::handle_request(RflexRole role, const core::Request& request) {
  switch (role) {
    case RflexRole::position: return position_request(request);
    case RflexRole::sonar:
    case RflexRole::ir: return ranger_request(role, request);
    case RflexRole::bumper: return bumper_request(request);
    default: return core::RequestResult::nack();  // power, aio, dio: none, as 1.5
  }
}

core::RequestResult RflexConnection::position_request(const core::Request& request) {
  class RflexBase final : public interfaces::PositionBase {
   public:
    explicit RflexBase(RflexConnection& robot) : robot_(robot) {}

    std::optional<interfaces::BaseGeometry> geometry() override {
      return interfaces::BaseGeometry{{}, robot_.settings_.mm_length / 1000.0, robot_.settings_.mm_width / 1000.0};
    }
    bool set_motor_power(bool on) override {
      return robot_.session_up_ && robot_.send(on ? hw::brake_release() : hw::brake_set());
    }
    // The RFLEX has one velocity mode: accepted, as 1.5 did.
    bool set_velocity_mode(std::uint8_t /*mode*/) override { return true; }
    bool reset_odometry() override {
      robot_.readings_.odometry().reset_reported();
      return true;
    }
    bool set_odometry(const geometry::Pose2& pose) override {
      robot_.readings_.odometry().set_reported(
          {pose.x * 1000.0, pose.y * 1000.0, pose.yaw});  // the integrator counts in mm
      return true;
    }

   private:
    RflexConnection& robot_;
  };
  RflexBase base(*this);
  return interfaces::answer_position_request(base, request);
}

core::RequestResult RflexConnection::ranger_request(RflexRole role, const core::Request& request) {
  class RflexRanger final : public interfaces::RangerArray {
   public:
    RflexRanger(RflexConnection& robot, RflexRole role) : robot_(robot), role_(role) {}

    std::optional<std::vector<geometry::Pose2>> sensor_poses() override {
      return role_ == RflexRole::sonar ? robot_.readings_.sonar_poses() : robot_.readings_.ir_poses();
    }
    bool set_power(bool on) override {
      if (!robot_.session_up_) return false;
      if (role_ == RflexRole::sonar) {
        robot_.sonar_wanted_ = on;
      } else {
        robot_.ir_wanted_ = on;
      }
      robot_.reconcile_subscriptions();  // sends it now
      return !robot_.link_error_;
    }

   private:
    RflexConnection& robot_;
    RflexRole role_;
  };
  RflexRanger ranger(*this, role);
  return role == RflexRole::sonar ? interfaces::answer_sonar_request(ranger, request)
                                  : interfaces::answer_ir_request(ranger, request);
}

core::RequestResult RflexConnection::bumper_request(const core::Request& request) {
  if (request.payload.size() == 1 && request.subtype() == protocol::kBumperGetGeomReq) {
    return core::RequestResult::ack(protocol::encode(readings_.bumper_geometry()));
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::drivers::rflex
