#include "square_drive.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "algorithms/geometry/pose2.hpp"
#include "client/typed/message_as.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::hardware_test {

using namespace std::chrono_literals;

void command_velocity(client::Client& client, protocol::DeviceAddress position, double speed, double turn_rate) {
  client::PositionCommand wanted;
  wanted.velocity = {speed, 0.0, turn_rate};
  client.write_command(position, protocol::encode(client::to_wire(wanted)));
}

namespace {

class SquareDriver {
 public:
  SquareDriver(client::Client& client, const SquareSettings& settings,
               const std::function<void(const protocol::Message&)>& observe)
      : client_(client), settings_(settings), observe_(observe) {}

  // Reads until `done` says so on fresh odometry or the leg's time is up.
  template <class Done>
  bool read_until(Done done, std::chrono::milliseconds limit) {
    const auto until = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < until) {
      if (auto message = client_.read(100ms)) take(*message);
      if (odometry_ && done(*odometry_)) return true;
    }
    return false;
  }

  SquareDrive drive() {
    SquareDrive result;
    if (settings_.enable_motors) {
      const auto power = protocol::encode(protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 1});
      const protocol::Message reply = client_.request(settings_.position, power);
      if (reply.type() != protocol::MessageType::kAck) {
        result.failure = "the motor power request was not acknowledged";
        return result;
      }
    }
    if (!read_until([](const client::PositionState&) { return true; }, 10s)) {
      result.failure = "no odometry within 10 s";
      return result;
    }
    for (int side = 0; side < 4 && result.failure.empty(); ++side) {
      if (!drive_side()) result.failure = "side " + std::to_string(side) + " did not end in time";
      stop();
      if (result.failure.empty() && !turn_left()) result.failure = "turn " + std::to_string(side) + " did not end in time";
      stop();
    }
    read_until([](const client::PositionState&) { return false; }, 500ms);
    result.finished = result.failure.empty();
    result.odometry = odometry_;
    return result;
  }

 private:
  void take(const protocol::Message& message) {
    if (observe_) observe_(message);
    if (message.type() == protocol::MessageType::kData && message.device() == settings_.position) {
      odometry_ = client::to_si(protocol::decode<protocol::PositionData>(message.payload));
    }
  }

  void stop() { command_velocity(client_, settings_.position, 0.0, 0.0); }

  bool drive_side() {
    const client::PositionState from = *odometry_;
    return read_until([&](const client::PositionState& now) {
      const double left = settings_.side - std::hypot(now.pose.x - from.pose.x, now.pose.y - from.pose.y);
      const double speed = std::clamp(1.5 * left, settings_.slowest_speed, settings_.top_speed);
      command_velocity(client_, settings_.position, speed, 0.0);
      return left <= settings_.distance_tolerance;
    }, settings_.leg_limit);
  }

  bool turn_left() {
    const double heading = odometry_->pose.yaw;
    return read_until([&](const client::PositionState& now) {
      const double left = std::numbers::pi / 2 - geometry::angle_difference(now.pose.yaw, heading);
      const double rate = std::clamp(2.0 * left, settings_.slowest_turn_rate, settings_.top_turn_rate);
      command_velocity(client_, settings_.position, 0.0, rate);
      return left <= settings_.heading_tolerance;
    }, settings_.leg_limit);
  }

  client::Client& client_;
  const SquareSettings& settings_;
  const std::function<void(const protocol::Message&)>& observe_;
  std::optional<client::PositionState> odometry_;
};

}  // namespace

SquareDrive drive_square(client::Client& client, const SquareSettings& settings,
                         const std::function<void(const protocol::Message&)>& observe) {
  return SquareDriver(client, settings, observe).drive();
}

}  // namespace playerkit::hardware_test
