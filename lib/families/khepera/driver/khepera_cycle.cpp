// The I/O thread's work with the devices: subscription edges, commands, the
// cycle of readings, publishing and requests (khepera.md §2, §3). Everything
// here runs with views_mutex_ held.
#include <algorithm>
#include <cmath>

#include "families/khepera/driver/khepera_connection.hpp"
#include "interfaces/position_data.hpp"
#include "links/link_error.hpp"
#include "interfaces/position_requests.hpp"
#include "interfaces/ranger_requests.hpp"
#include "interfaces/wire_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/errors.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers::khepera {

namespace hw = hardware::khepera;

namespace {

constexpr double kMillimetresPerMetre = 1000.0;

geometry::Pose2 scaled_metres(const geometry::Pose2& millimetres, double scale) {
  return {millimetres.x * scale / kMillimetresPerMetre, millimetres.y * scale / kMillimetresPerMetre, millimetres.yaw};
}

}  // namespace

bool KheperaConnection::has_view(KheperaRole role) const {
  return std::any_of(views_.begin(), views_.end(), [role](const View& view) { return view.role == role; });
}

void KheperaConnection::reconcile_subscriptions() {
  // As 1.5: the first position device stops the wheels and zeroes the
  // counters, with the motors off until MOTOR_POWER; the last one stops them.
  const bool position = has_view(KheperaRole::position);
  if (position && !position_active_) {
    position_active_ = true;
    motors_on_ = false;
    speed_ = turn_rate_ = 0.0;
    (void)ask(hw::set_speed(0, 0), 0);
    (void)ask(hw::set_position(0, 0), 0);
    last_counters_ = Counters{};
    odometry_ = {};
  } else if (!position && position_active_) {
    position_active_ = false;
    motors_on_ = false;
    speed_ = turn_rate_ = 0.0;
    (void)ask(hw::set_speed(0, 0), 0);
  }
  const bool ir = has_view(KheperaRole::ir);
  if (ir && !ir_active_) proximity_.clear();  // 1.5 zeroed the ranges for a new client
  ir_active_ = ir;
}

void KheperaConnection::serve_requests() {
  for (const View& view : views_) {
    if (view.device->pending_requests() > 0) view.device->service_requests();
  }
}

void KheperaConnection::take_commands() {
  for (const View& view : views_) {
    if (view.role != KheperaRole::position) continue;
    auto command = view.device->take_command();
    if (!command) continue;
    try {
      const auto decoded = protocol::decode<protocol::PositionCommand>(command->payload);
      speed_ = decoded.xspeed / kMillimetresPerMetre;
      turn_rate_ = interfaces::radians(decoded.yawspeed);
    } catch (const protocol::DecodeError&) {
      continue;  // the device checked the size
    }
    // While the robot is away commands are dropped: nothing old is replayed.
    if (session_up_ && position_active_) send_speeds();
  }
}

hw::WheelSpeeds KheperaConnection::wheel_command() const {
  return motors_on_ ? hw::wheel_speeds(speed_, turn_rate_, position_options_.wheels, hw::kFastestWheel)
                    : hw::WheelSpeeds{};
}

void KheperaConnection::send_speeds() {
  const hw::WheelSpeeds wheels = wheel_command();
  (void)ask(hw::set_speed(wheels.left, wheels.right), 0);
}

bool KheperaConnection::try_ask(const hw::Message& command) {
  if (lost_reason_) return false;
  try {
    (void)ask(command, 0);
    return true;
  } catch (const hardware_driver::RobotLost& e) {
    lost_reason_ = e.what();  // serve() loses the robot once the requests are answered
  } catch (const links::LinkError& e) {
    lost_reason_ = e.what();
  }
  return false;
}

void KheperaConnection::run_cycle() {
  if (position_active_) send_speeds();
  // N every cycle, as 1.5, so a client subscribing finds readings at once;
  // a robot with fewer sensors than pose_count fills only theirs.
  proximity_ = ask(hw::read_proximity(), std::nullopt).values;
  const auto counters = ask(hw::read_position(), 2);
  const auto speeds = ask(hw::read_speed(), 2);
  const hw::WheelGeometry& wheels = position_options_.wheels;
  const Counters now{counters.values[0], counters.values[1]};
  if (last_counters_) {
    const auto motion = hw::body_motion(static_cast<double>(hw::counter_step(now.left, last_counters_->left)),
                                        static_cast<double>(hw::counter_step(now.right, last_counters_->right)),
                                        wheels);
    odometry_.drive(motion.distance, motion.turn);
  }
  last_counters_ = now;
  const auto rate = hw::body_motion(static_cast<double>(speeds.values[0]), static_cast<double>(speeds.values[1]),
                                    wheels);
  velocity_ = {rate.distance / hw::kSpeedPeriodSeconds, 0.0, rate.turn / hw::kSpeedPeriodSeconds};
  fresh_readings_ = true;
  ++cycles_;
}

void KheperaConnection::publish() {
  if (views_.empty() || !fresh_readings_) return;
  fresh_readings_ = false;
  const core::Timestamp stamp = views_.front().device->clock().now();
  for (const View& view : views_) {
    if (view.role == KheperaRole::position) {
      view.device->publish(
          protocol::encode(interfaces::position_data(odometry_.reported(), velocity_, false,
                                                     interfaces::HeadingRange::from_0_to_360)),
          stamp);
      continue;
    }
    protocol::IrData data;
    const auto count = std::min({proximity_.size(), ir_options_.sensors.size(), data.ranges.size()});
    data.range_count = static_cast<std::uint16_t>(count);
    for (std::size_t i = 0; i < count; ++i) {
      const std::int64_t reading = proximity_[i];
      data.voltages[i] = interfaces::wire_value<std::uint16_t>(static_cast<double>(reading));
      data.ranges[i] = interfaces::wire_value<std::uint16_t>(
          options_.scale * hw::ir_range_mm(reading, ir_options_.sensors[i].calibration));
    }
    view.device->publish(protocol::encode(data), stamp);
  }
}

// ---------------------------------------------------------------- requests

core::RequestResult KheperaConnection::handle_request(KheperaRole role, const core::Request& request) {
  return role == KheperaRole::position ? position_request(request) : ir_request(request);
}

core::RequestResult KheperaConnection::position_request(const core::Request& request) {
  class Base final : public interfaces::PositionBase {
   public:
    explicit Base(KheperaConnection& robot) : robot_(robot) {}

    std::optional<interfaces::BaseGeometry> geometry() override {
      const KheperaPositionOptions& options = robot_.position_options_;
      const double scale = robot_.options_.scale / kMillimetresPerMetre;
      return interfaces::BaseGeometry{scaled_metres(options.pose, robot_.options_.scale), options.length_mm * scale,
                                      options.width_mm * scale};
    }
    bool set_motor_power(bool on) override {
      robot_.motors_on_ = on;
      if (!robot_.session_up_ || !robot_.position_active_) return true;  // sent when the robot is back
      const hw::WheelSpeeds wheels = robot_.wheel_command();
      return robot_.try_ask(hw::set_speed(wheels.left, wheels.right));
    }
    // One mode only: the wheels' speeds (1.5 ACKed and did nothing).
    bool set_velocity_mode(std::uint8_t /*mode*/) override { return true; }
    bool reset_odometry() override {
      if (!robot_.session_up_ || !robot_.try_ask(hw::set_position(0, 0))) return false;
      robot_.last_counters_ = Counters{};
      robot_.odometry_ = {};
      return true;
    }
    // The values are honoured (1.5 reset to zero whatever they were).
    bool set_odometry(const geometry::Pose2& pose) override {
      robot_.odometry_.set_reported(pose);
      return true;
    }

   private:
    KheperaConnection& robot_;
  };
  Base base(*this);
  return interfaces::answer_position_request(base, request);
}

core::RequestResult KheperaConnection::ir_request(const core::Request& request) {
  class Ir final : public interfaces::RangerArray {
   public:
    explicit Ir(KheperaConnection& robot) : robot_(robot) {}
    std::optional<std::vector<geometry::Pose2>> sensor_poses() override {
      std::vector<geometry::Pose2> poses;
      for (const KheperaIrSensor& sensor : robot_.ir_options_.sensors) {
        poses.push_back(scaled_metres(sensor.pose, robot_.options_.scale));
      }
      return poses;
    }

   private:
    KheperaConnection& robot_;
  };
  Ir ir(*this);
  return interfaces::answer_ir_request(ir, request);
}

}  // namespace playerkit::drivers::khepera
