// Requests to the p2os devices (p2os.md §3): each device has its own queue
// and they are answered on the I/O thread, so a request that sends a
// command to the robot is ACKed once the command is on the line. Requests
// that need the robot are NACKed while it is not answering.
#include <cmath>
#include <numbers>

#include "families/p2os/driver/cmucam_commands.hpp"
#include "families/p2os/driver/p2os_connection.hpp"
#include "families/p2os/driver/robot_geometry.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;

core::RequestResult P2osConnection::handle_request(P2osRole role, const core::Request& request) {
  switch (role) {
    case P2osRole::position: return position_request(request);
    case P2osRole::sonar: return sonar_request(request);
    case P2osRole::cmucam: return blobfinder_request(request);
    default:
      // gripper, power (MAIN_POWER_REQ too), bumper (GET_GEOM too), aio,
      // dio, compass, gyro, sound: none, as in 1.5.
      return core::RequestResult::nack();
  }
}

core::RequestResult P2osConnection::position_request(const core::Request& request) {
  const std::size_t size = request.payload.size();
  switch (request.subtype()) {
    case protocol::kPositionGetGeomReq:
      if (size != 1) break;  // the subtype alone
      return core::RequestResult::ack(protocol::encode(position_geometry()));
    case protocol::kPositionMotorPowerReq: {
      if (size != protocol::PositionPowerConfig::kWireSize || !session_up_) break;
      const bool on = request.payload[1] != 0;
      if (!send(hw::Command::with_integer(hw::command::enable, on ? 1 : 0))) break;
      motors_wanted_ = on;
      motors_sent_ = on;
      return core::RequestResult::ack();
    }
    case protocol::kPositionVelocityModeReq:
      if (size != protocol::PositionVelocityModeConfig::kWireSize) break;
      velocity_mode_ = request.payload[1] == 0 ? VelocityMode::direct_wheel : VelocityMode::separate;
      return core::RequestResult::ack();
    case protocol::kPositionResetOdomReq:
      if (size != protocol::PositionResetOdomConfig::kWireSize || !session_up_) break;
      if (!send(hw::Command::type_only(hw::command::seto))) break;
      odometry_.robot_reset_sent();
      return core::RequestResult::ack();
    case protocol::kPositionSetOdomReq: {
      if (size != protocol::PositionSetOdomRequest::kWireSize) break;
      const auto pose = protocol::decode<protocol::PositionSetOdomRequest>(request.payload);
      // The whole theta, in degrees (1.5 used its upper 16 bits, quirk 6).
      odometry_.set_pose({double(pose.x), double(pose.y), pose.theta * std::numbers::pi / 180.0});
      return core::RequestResult::ack();
    }
    default:
      break;
  }
  return core::RequestResult::nack();
}

core::RequestResult P2osConnection::sonar_request(const core::Request& request) {
  const std::size_t size = request.payload.size();
  switch (request.subtype()) {
    case protocol::kSonarGetGeomReq:
      if (size != 1) break;  // the subtype alone
      return core::RequestResult::ack(protocol::encode(sonar_geometry(*params_)));
    case protocol::kSonarPowerReq: {
      if (size != protocol::SonarPowerConfig::kWireSize || !session_up_) break;
      const bool on = request.payload[1] != 0;
      if (!send(hw::Command::with_integer(hw::command::sonar, on ? 1 : 0))) break;
      sonar_wanted_ = on;
      sonar_sent_ = on;
      return core::RequestResult::ack();
    }
    default:
      break;
  }
  return core::RequestResult::nack();
}

core::RequestResult P2osConnection::blobfinder_request(const core::Request& request) {
  const std::size_t size = request.payload.size();
  switch (request.subtype()) {
    case protocol::kBlobfinderSetColorReq: {
      if (size != protocol::BlobfinderColorConfig::kWireSize || !session_up_) break;
      cmucam_tracking_text_ = tracking_text(protocol::decode<protocol::BlobfinderColorConfig>(request.payload));
      // Tracking starts with this colour once the camera is out of its reset.
      if (cmucam_phase_ == CmucamPhase::tracking && !send_all(cmucam_track_commands(cmucam_tracking_text_))) break;
      return core::RequestResult::ack();
    }
    case protocol::kBlobfinderSetImagerParamsReq: {
      if (size != protocol::BlobfinderImagerConfig::kWireSize || !session_up_) break;
      const auto text = imager_text(protocol::decode<protocol::BlobfinderImagerConfig>(request.payload));
      if (text && !(send(cmucam_stop_command()) &&
                    send(hw::Command::with_string(hw::command::tty3, *text)))) {
        break;
      }
      if (text && cmucam_phase_ == CmucamPhase::tracking &&
          !send_all(cmucam_track_commands(cmucam_tracking_text_))) {
        break;
      }
      return core::RequestResult::ack();
    }
    default:
      break;
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::drivers::p2os
