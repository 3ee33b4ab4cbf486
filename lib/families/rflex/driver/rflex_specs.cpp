// The seven driver specs, one per role (rflex.md table 1, manual §7.34), and
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/shared_connection.hpp"
#include "families/rflex/driver/rflex_connection.hpp"
#include "families/rflex/driver/rflex_device_driver.hpp"
#include "families/rflex/driver/rflex_drivers.hpp"
#include "families/rflex/driver/rflex_options.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using protocol::Access;
using rflex::RflexRole;

core::DriverSpec make_spec(RflexRole role, std::uint16_t interface, std::string summary,
                           std::vector<std::string> requests, std::string example) {
  core::DriverSpec spec;
  spec.name = std::string(rflex::driver_name(role));
  spec.interfaces = {interface};
  spec.access = role == RflexRole::position ? Access::kAll : Access::kRead;
  spec.factory = [role](const core::DriverContext& context) {
    const rflex::RflexSettings settings = rflex::read_rflex_settings(context);
    auto connection = context.connections.get<rflex::RflexConnection>(
        rflex::connection_key(settings),
        [&] { return std::make_shared<rflex::RflexConnection>(settings, context.logger); });
    return std::make_unique<rflex::RflexDeviceDriver>(role, std::move(connection));
  };
  // Each device has its own queue (1.5 shared one of length 1 between all seven).
  spec.limits = core::DeviceLimits{.request_queue = 8};
  spec.summary = std::move(summary);
  spec.doc.manual_section = "7.34";
  spec.doc.needs_hardware = true;
  spec.doc.schema = rflex::rflex_option_schema(role);
  spec.doc.requests = std::move(requests);
  spec.doc.example = std::move(example);
  return spec;
}

core::DriverSpec spec_of(RflexRole role) {
  switch (role) {
    case RflexRole::position:
      return make_spec(role, protocol::kPositionCode,
                       "iRobot/RWI RFLEX wheels (B21r, ATRV, Magellan): odometry, velocity commands, brakes",
                       {"GET_GEOM: pose (0, 0, 0), size mm_length x mm_width",
                        "MOTOR_POWER: 0 sets the brake, other values release it",
                        "VELOCITY_MODE: accepted, nothing changes (one mode)",
                        "RESET_ODOM: the reported pose becomes (0, 0, 0)",
                        "SET_ODOM: the reported pose becomes x, y (mm), theta (degrees)", "others: NACK"},
                       "position:0 ( driver \"rflex_position\" rflex_serial_port \"/dev/ttyR0\" "
                       "odo_distance_conversion 103 odo_angle_conversion 35000 )");
    case RflexRole::sonar:
      return make_spec(role, protocol::kSonarCode, "RFLEX sonar boards: ranges in mm, in bank order",
                       {"GET_GEOM: the mmrad_sonar_poses", "POWER: SONAR_RUN on/off", "others: NACK"},
                       "sonar:0 ( driver \"rflex_sonar\" num_sonars 24 range_distance_conversion 1.476 )");
    case RflexRole::ir:
      return make_spec(role, protocol::kIrCode, "RFLEX infrared banks: raw readings and calibrated ranges",
                       {"POSE: the configured poses", "POWER: IR_RUN on/off (the 2-byte request)", "others: NACK"},
                       "ir:0 ( driver \"rflex_ir\" rflex_bank_count 2 rflex_banks [8 8] )");
    case RflexRole::bumper:
      return make_spec(role, protocol::kBumperCode, "RFLEX bump panels: the corner bits of each panel",
                       {"GET_GEOM: the bumper_def panels", "others: NACK"},
                       "bumper:0 ( driver \"rflex_bumper\" bumper_count 14 )");
    case RflexRole::power:
      return make_spec(role, protocol::kPowerCode, "RFLEX battery voltage in decivolts", {"none: NACK"},
                       "power:0 ( driver \"rflex_power\" rflex_power_offset 12 )");
    case RflexRole::aio:
      return make_spec(role, protocol::kAioCode, "RFLEX analog inputs: none known, empty data", {"none: NACK"},
                       "aio:0 ( driver \"rflex_aio\" )");
    case RflexRole::dio:
      return make_spec(role, protocol::kDioCode, "RFLEX digital inputs: none known, empty data", {"none: NACK"},
                       "dio:0 ( driver \"rflex_dio\" )");
  }
  throw std::logic_error("rflex: a role without a spec");
}

}  // namespace

std::vector<core::DriverSpec> rflex_driver_specs() {
  std::vector<core::DriverSpec> specs;
  for (const RflexRole role : rflex::all_rflex_roles()) specs.push_back(spec_of(role));
  return specs;
}

}  // namespace playerkit::drivers
