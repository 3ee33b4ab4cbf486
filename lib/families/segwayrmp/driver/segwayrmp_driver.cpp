// Each device a view onto the robot's shared RmpConnection, whose I/O
// thread publishes its data, takes its commands and answers its requests.
#include "families/segwayrmp/driver/segwayrmp_driver.hpp"

#include <memory>

#include "core/driver.hpp"
#include "core/shared_connection.hpp"
#include "families/segwayrmp/driver/rmp_connection.hpp"
#include "families/segwayrmp/driver/rmp_options.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using segwayrmp::RmpConnection;
using segwayrmp::RmpRole;

class RmpDeviceDriver final : public core::Driver {
 public:
  RmpDeviceDriver(RmpRole role, std::shared_ptr<RmpConnection> connection)
      : role_(role), connection_(std::move(connection)) {}
  ~RmpDeviceDriver() override {
    if (use_) {
      connection_->remove_device(device());
      use_ = {};
    }
  }

  void setup() override {
    core::SharedConnection::Use use = connection_->attach();  // the first device opens the bus
    connection_->add_device(role_, device());
    use_ = std::move(use);
  }
  void shutdown() override {
    if (!use_) return;
    connection_->remove_device(device());
    use_ = {};  // the last one stops the robot and closes the bus
  }
  [[nodiscard]] bool runs_own_thread() const override { return true; }
  [[nodiscard]] bool setup_may_block() const override { return true; }
  core::RequestResult handle_request(const core::Request& request) override {
    return connection_->handle_request(role_, request);
  }
  [[nodiscard]] std::vector<core::DriverCounter> counters() const override { return connection_->counters(); }
  bool set_byte_trace(core::ByteTrace trace) override {
    connection_->set_byte_trace(std::move(trace));
    return true;
  }

 private:
  const RmpRole role_;
  const std::shared_ptr<RmpConnection> connection_;
  core::SharedConnection::Use use_;
};

RmpRole role_of(std::uint16_t interface) {
  if (interface == protocol::kPosition3dCode) return RmpRole::position3d;
  if (interface == protocol::kPowerCode) return RmpRole::power;
  return RmpRole::position;
}

std::unique_ptr<core::Driver> make_device(const core::DriverContext& context) {
  segwayrmp::RmpSettings settings = segwayrmp::read_rmp_settings(context);
  auto connection = context.connections.get<RmpConnection>(segwayrmp::connection_key(settings), [&] {
    return std::make_shared<RmpConnection>(std::move(settings), context.logger);
  });
  return std::make_unique<RmpDeviceDriver>(role_of(context.key.address.interface), std::move(connection));
}

}  // namespace

std::vector<core::DriverSpec> segwayrmp_driver_specs() {
  const std::vector<std::string> requests{
      "position MOTOR_POWER: enables (1) or disables (0) acting on commands; disabled at setup, so send it first",
      "position GET_GEOM: pose (0, 0, 0), size 508 x 610 mm",
      "position RESET_ODOM: the robot's integrators reset (status 50, 0x0F, twice), the odometry (0, 0, 0)",
      "position RMP_VELOCITY_SCALE .. RMP_CURRENT_LIMIT (51-55): status commands 10-14, the value's low byte",
      "position RMP_RST_INTEGRATORS (56): status 50 with the value's bits (1 right, 2 left, 4 yaw, 8 fore/aft)",
      "position RMP_SHUTDOWN (57): the robot powers down (frame 0x412)",
      "position3d MOTOR_POWER: as position's; other requests NACK",
      "power: no requests (NACK)"};
  core::DriverSpec robot{
      .name = "segwayrmp",
      .interfaces = {protocol::kPositionCode, protocol::kPosition3dCode, protocol::kPowerCode},
      .access = protocol::Access::kAll,
      .factory = make_device,
      .limits = {},
      .summary = "Segway RMP over CAN (SocketCAN or an slcan adapter): position, position3d, power",
      .family = "segwayrmp",
      .doc = {.manual_section = "7.37",
              .needs_hardware = true,
              .options = {},
              .requests = requests,
              .example = "position:0 ( driver \"segwayrmp\" canio \"slcan\" port \"/dev/ttyUSB0\" max_xspeed 500 "
                         "max_yawspeed 40 )",
              .schema = segwayrmp::rmp_option_schema()},
  };
  core::DriverSpec position = robot;
  position.name = "rmpposition";
  position.interfaces = {protocol::kPositionCode, protocol::kPosition3dCode};
  position.summary = "1.5's name of the Segway RMP's position and position3d devices (`segwayrmp`)";
  position.doc.example = "position:0 ( driver \"rmpposition\" canio \"socketcan\" device \"can0\" )";
  core::DriverSpec power = robot;
  power.name = "rmppower";
  power.interfaces = {protocol::kPowerCode};
  power.access = protocol::Access::kRead;
  power.summary = "1.5's name of the Segway RMP's power device (battery, `segwayrmp`)";
  power.doc.example = "power:0 ( driver \"rmppower\" canio \"socketcan\" device \"can0\" )";
  return {robot, position, power};
}

}  // namespace playerkit::drivers
