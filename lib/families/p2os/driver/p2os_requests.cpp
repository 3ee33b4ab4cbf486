// Requests to the p2os devices (p2os.md §3): each device has its own queue
// and they are answered on the I/O thread, so a request that sends a
// command to the robot is ACKed once the command is on the line. Requests
// that need the robot are NACKed while it is not answering.
#include <optional>
#include <vector>

#include "families/p2os/driver/cmucam_commands.hpp"
#include "families/p2os/driver/p2os_connection.hpp"
#include "families/p2os/driver/robot_geometry.hpp"
#include "interfaces/position_requests.hpp"
#include "interfaces/ranger_requests.hpp"
#include "interfaces/wire_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/blobfinder.hpp"

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
  // The robot's side of the position requests (p2os.md §3.1); the adapter
  // checks sizes and makes the replies. POSITION_MODE, the PIDs, the speed
  // profile and the RMP settings stay declined, as in 1.5.
  class RobotBase final : public interfaces::PositionBase {
   public:
    explicit RobotBase(P2osConnection& robot) : robot_(robot) {}

    std::optional<interfaces::BaseGeometry> geometry() override { return base_geometry(); }

    bool set_motor_power(bool on) override {
      if (!robot_.session_up_ || !robot_.send(hw::Command::with_integer(hw::command::enable, on ? 1 : 0))) {
        return false;
      }
      robot_.motors_wanted_ = on;
      robot_.motors_sent_ = on;
      return true;
    }
    bool set_velocity_mode(std::uint8_t mode) override {
      robot_.velocity_mode_ = mode == 0 ? VelocityMode::direct_wheel : VelocityMode::separate;
      return true;
    }
    bool reset_odometry() override {
      if (!robot_.session_up_ || !robot_.send(hw::Command::type_only(hw::command::seto))) return false;
      robot_.odometry_.robot_reset_sent();
      return true;
    }
    bool set_odometry(const geometry::Pose2& pose) override {
      // The tracker counts in millimetres.
      robot_.odometry_.set_pose({pose.x * interfaces::kMillimetresPerMetre,
                                 pose.y * interfaces::kMillimetresPerMetre, pose.yaw});
      return true;
    }

   private:
    P2osConnection& robot_;
  };
  RobotBase base(*this);
  return interfaces::answer_position_request(base, request);
}

core::RequestResult P2osConnection::sonar_request(const core::Request& request) {
  class RobotSonar final : public interfaces::RangerArray {
   public:
    explicit RobotSonar(P2osConnection& robot) : robot_(robot) {}

    std::optional<std::vector<geometry::Pose2>> sensor_poses() override { return sonar_poses(*robot_.params_); }
    bool set_power(bool on) override {
      if (!robot_.session_up_ || !robot_.send(hw::Command::with_integer(hw::command::sonar, on ? 1 : 0))) {
        return false;
      }
      robot_.sonar_wanted_ = on;
      robot_.sonar_sent_ = on;
      return true;
    }

   private:
    P2osConnection& robot_;
  };
  RobotSonar sonar(*this);
  return interfaces::answer_sonar_request(sonar, request);
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
