// The eleven driver specs, one per role: interfaces, access and
// documentation (p2os.md table 1, §4.1; manual §7.30).
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "families/p2os/driver/p2os_connection.hpp"
#include "families/p2os/driver/p2os_device_driver.hpp"
#include "families/p2os/driver/p2os_drivers.hpp"
#include "families/p2os/driver/p2os_options.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using p2os::P2osRole;
using protocol::Access;

core::DriverSpec make_spec(P2osRole role, std::uint16_t interface, Access access, std::string summary,
                           std::vector<std::string> requests, std::string example) {
  core::DriverSpec spec;
  spec.name = std::string(p2os::driver_name(role));
  spec.interfaces = {interface};
  spec.access = access;
  spec.factory = [role](const core::DriverContext& context) {
    const p2os::RobotLinkOptions options = p2os::read_robot_link_options(context);
    const p2os::MotorLimits limits =
        role == P2osRole::position ? p2os::read_motor_limits(context) : p2os::MotorLimits{};
    auto connection = context.connections.get<p2os::P2osConnection>(
        p2os::connection_key(options),
        [&] { return std::make_shared<p2os::P2osConnection>(options, context.logger); });
    return std::make_unique<p2os::P2osDeviceDriver>(role, std::move(connection), limits);
  };
  // Each device has its own queue (1.5 shared one of length 1 between all
  // eleven, so concurrent requests got ERR).
  spec.limits = core::DeviceLimits{.request_queue = 8};
  spec.summary = std::move(summary);
  spec.doc.manual_section = "7.30";
  spec.doc.needs_hardware = true;
  spec.doc.schema = p2os::p2os_option_schema(role);  // the robot's options; p2os_position's own too
  spec.doc.requests = std::move(requests);
  spec.doc.example = std::move(example);
  return spec;
}

// What each role's driver serves and says of itself; its name is the role's
// (p2os_role.hpp).
core::DriverSpec spec_of(P2osRole role) {
  switch (role) {
    case P2osRole::position: {
      core::DriverSpec spec = make_spec(
          role, protocol::kPositionCode, Access::kAll,
          "Pioneer (P2OS) wheels: odometry, velocity commands, motor power",
          {"GET_GEOM: centre of rotation (-100, 0) mm, body 500 x 450 mm (every robot, as 1.5)",
           "MOTOR_POWER: ENABLE 1/0 (the motors are off after every first subscription)",
           "VELOCITY_MODE: 0 direct wheel speeds (VEL2), other values separate VEL/RVEL",
           "RESET_ODOM: SETO; the reported pose becomes (0, 0, 0)",
           "SET_ODOM: the reported pose becomes x, y (mm), theta (degrees)", "others: NACK"},
          "position:0 ( driver \"p2os_position\" port \"/dev/ttyUSB0\" max_xspeed 400 )");
      return spec;
    }
    case P2osRole::sonar:
      return make_spec(role, protocol::kSonarCode, Access::kRead,
                       "Pioneer (P2OS) sonar ring: ranges in mm, index 0 front left, clockwise",
                       {"GET_GEOM: one pose per transducer of the robot's row (x, y mm, heading deg)",
                        "POWER: SONAR 1/0 (on with the first subscription, off after the last)", "others: NACK"},
                       "sonar:0 ( driver \"p2os_sonar\" )");
    case P2osRole::gripper:
      return make_spec(role, protocol::kGripperCode, Access::kAll,
                       "Pioneer (P2OS) gripper: paddle/lift state and beams; GRIPPER commands",
                       {"none: every request gets NACK"}, "gripper:0 ( driver \"p2os_gripper\" )");
    case P2osRole::power:
      return make_spec(role, protocol::kPowerCode, Access::kRead, "Pioneer (P2OS) battery voltage in decivolts",
                       {"none: every request gets NACK (MAIN_POWER_REQ too, as 1.5)"},
                       "power:0 ( driver \"p2os_power\" )");
    case P2osRole::bumper:
      return make_spec(role, protocol::kBumperCode, Access::kRead,
                       "Pioneer (P2OS) bumpers: 5 front then 5 rear switches",
                       {"none: every request gets NACK (GET_GEOM too, as 1.5)"},
                       "bumper:0 ( driver \"p2os_bumper\" )");
    case P2osRole::aio:
      return make_spec(role, protocol::kAioCode, Access::kRead,
                       "Pioneer (P2OS) analog input: the selected port, 0-255", {"none: every request gets NACK"},
                       "aio:0 ( driver \"p2os_aio\" )");
    case P2osRole::dio:
      return make_spec(role, protocol::kDioCode, Access::kRead, "Pioneer (P2OS) digital inputs: 8 bits",
                       {"none: every request gets NACK"}, "dio:0 ( driver \"p2os_dio\" )");
    case P2osRole::cmucam:
      return make_spec(role, protocol::kBlobfinderCode, Access::kRead,
                       "CMUcam on a Pioneer's AUX2 port (P2OS): one tracked blob",
                       {"SET_COLOR: track rmin..bmax (TC), or whatever is in view when any is negative (TW)",
                        "SET_IMAGER_PARAMS: brightness, contrast, colour mode, auto gain (CR)", "others: NACK"},
                       "blobfinder:0 ( driver \"p2os_cmucam\" )");
    case P2osRole::compass:
      return make_spec(role, protocol::kPositionCode, Access::kRead,
                       "Pioneer (P2OS) compass heading in the yaw of position data",
                       {"none: every request gets NACK"}, "position:1 ( driver \"p2os_compass\" )");
    case P2osRole::gyro:
      return make_spec(role, protocol::kPositionCode, Access::kRead,
                       "Pioneer (P2OS) gyro: the raw rate (512 at rest) in the yawspeed of position data",
                       {"none: every request gets NACK"}, "position:2 ( driver \"p2os_gyro\" )");
    case P2osRole::sound:
      return make_spec(role, protocol::kSoundCode, Access::kAll,
                       "Pioneer/AmigoBot (P2OS) stored sounds: play one by index",
                       {"none: every request gets NACK"}, "sound:0 ( driver \"p2os_sound\" )");
  }
  throw std::logic_error("p2os: a role without a spec");
}

}  // namespace

std::vector<core::DriverSpec> p2os_driver_specs() {
  std::vector<core::DriverSpec> specs;
  for (const P2osRole role : p2os::all_p2os_roles()) specs.push_back(spec_of(role));
  return specs;
}

}  // namespace playerkit::drivers
