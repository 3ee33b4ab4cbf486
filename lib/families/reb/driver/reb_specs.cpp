// The three driver specs (reb.md table, manual §7.33).
#include <memory>
#include <string>
#include <vector>

#include "families/reb/driver/reb_connection.hpp"
#include "families/reb/driver/reb_device_driver.hpp"
#include "families/reb/driver/reb_drivers.hpp"
#include "families/reb/driver/reb_options.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using protocol::Access;
using reb::RebRole;

core::DriverSpec make_spec(RebRole role, std::uint16_t interface, Access access, std::string summary,
                           std::vector<std::string> requests, std::string example) {
  core::DriverSpec spec;
  spec.name = std::string(reb::driver_name(role));
  spec.interfaces = {interface};
  spec.access = access;
  spec.factory = [role](const core::DriverContext& context) {
    const reb::RebLinkOptions options = reb::read_reb_link_options(context);
    const bool heading_control = role == RebRole::position && reb::read_heading_control(context);
    auto connection = context.connections.get<reb::RebConnection>(
        reb::connection_key(options), [&] { return std::make_shared<reb::RebConnection>(options, context.logger); });
    return std::make_unique<reb::RebDeviceDriver>(role, std::move(connection), heading_control);
  };
  // Each device has its own queue (1.5 shared one of length 1 between the three).
  spec.limits = core::DeviceLimits{.request_queue = 8};
  spec.summary = std::move(summary);
  spec.doc.manual_section = "7.33";
  spec.doc.needs_hardware = true;
  spec.doc.schema = reb::reb_option_schema(role);
  spec.doc.requests = std::move(requests);
  spec.doc.example = std::move(example);
  return spec;
}

}  // namespace

std::vector<core::DriverSpec> reb_driver_specs() {
  return {
      make_spec(RebRole::position, protocol::kPositionCode, Access::kAll,
                "UMass UBot (REB, LPRSerCom) wheels: odometry, velocity, heading and position control",
                {"GET_GEOM: centre (0, 0), body 180 x 180 mm",
                 "MOTOR_POWER: motors on/off (off after every first subscription, as 1.5)",
                 "VELOCITY_MODE: 0 velocities as commanded, other values heading control (turn towards yaw)",
                 "POSITION_MODE: 1 position control (a new xspeed is a move of that many mm, a new yawspeed a "
                 "turn of that many degrees; stall 1 once on target), 0 back to velocity control",
                 "RESET_ODOM, SET_ODOM: the board's counters zeroed (G), the pose becomes (0,0,0) or x, y, theta",
                 "SPEED_PID, POSITION_PID: A and F to both motors",
                 "SPEED_PROF: J to both motors (mm/s and mm/s^2 as pulses per 10 ms)", "others: NACK"},
                "position:0 ( driver \"reb_position\" port \"/dev/ttySA1\" subclass \"slow\" )"),
      make_spec(RebRole::ir, protocol::kIrCode, Access::kRead,
                "UMass UBot (REB) IR sensors: eight voltages in mV, clients convert them to ranges",
                {"POSE: the eight sensors' poses (x, y mm, heading deg)", "POWER: emitters on (Y,1) / off (Y,0)",
                 "others: NACK"},
                "ir:0 ( driver \"reb_ir\" )"),
      make_spec(RebRole::power, protocol::kPowerCode, Access::kRead,
                "UMass UBot (REB) battery voltage in decivolts (A/D channel 15)",
                {"none: every request gets NACK"}, "power:0 ( driver \"reb_power\" )"),
  };
}

}  // namespace playerkit::drivers
