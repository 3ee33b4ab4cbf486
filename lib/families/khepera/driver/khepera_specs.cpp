// The two driver specs (khepera.md table 1, §3.4, §4; manual §7.21).
#include <memory>
#include <string>
#include <vector>

#include "families/khepera/driver/khepera_device_driver.hpp"
#include "families/khepera/driver/khepera_drivers.hpp"
#include "families/khepera/driver/khepera_options.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using namespace khepera;

std::shared_ptr<KheperaConnection> robot_of(const core::DriverContext& context) {
  const KheperaRobotOptions options = read_khepera_robot_options(context);
  return context.connections.get<KheperaConnection>(
      connection_key(options), [&] { return std::make_shared<KheperaConnection>(options, context.logger); });
}

core::DriverSpec common_spec() {
  core::DriverSpec spec;
  // Each device its own queue (1.5's held one request and dropped the
  // second reply of a NACKed one).
  spec.limits = core::DeviceLimits{.request_queue = 8};
  spec.doc.manual_section = "7.21";
  spec.doc.needs_hardware = true;
  return spec;
}

core::DriverSpec position_spec() {
  core::DriverSpec spec = common_spec();
  spec.name = std::string(kPositionDriver);
  spec.interfaces = {protocol::kPositionCode};
  spec.access = protocol::Access::kAll;
  spec.factory = [](const core::DriverContext& context) {
    KheperaPositionOptions position = read_khepera_position_options(context);
    return std::make_unique<KheperaDeviceDriver>(robot_of(context), std::move(position));
  };
  spec.summary = "K-Team Khepera wheels: odometry, velocity commands, motor power";
  spec.doc.schema = khepera_position_schema();
  spec.doc.requests = {
      "GET_GEOM: pose and size x scale_factor (default (0, 0, 0), 570 x 570 mm, as 1.5)",
      "MOTOR_POWER: 1 drives, 0 sends D,0,0 (the motors are off after every first subscription)",
      "VELOCITY_MODE: ACK, nothing changes (one mode: wheel speeds)",
      "RESET_ODOM: G,0,0; the reported pose becomes (0, 0, 0)",
      "SET_ODOM: the reported pose becomes x, y (mm), theta (degrees) (1.5 reset to zero)",
      "others: NACK"};
  spec.doc.example = "position:0 ( driver \"khepera_position\" port \"/dev/ttyUSB0\" )";
  return spec;
}

core::DriverSpec ir_spec() {
  core::DriverSpec spec = common_spec();
  spec.name = std::string(kIrDriver);
  spec.interfaces = {protocol::kIrCode};
  spec.access = protocol::Access::kRead;
  spec.factory = [](const core::DriverContext& context) {
    KheperaIrOptions ir = read_khepera_ir_options(context);
    return std::make_unique<KheperaDeviceDriver>(robot_of(context), std::move(ir));
  };
  spec.summary = "K-Team Khepera proximity sensors: readings 0-1023 and ranges (mm x scale_factor)";
  spec.doc.schema = khepera_ir_schema();
  spec.doc.requests = {"POSE: each sensor's x, y (mm x scale_factor) and heading (deg)", "others: NACK"};
  spec.doc.example = "ir:0 ( driver \"khepera_ir\" )";
  return spec;
}

}  // namespace

std::vector<core::DriverSpec> khepera_driver_specs() { return {position_spec(), ir_spec()}; }

}  // namespace playerkit::drivers
