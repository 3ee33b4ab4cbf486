// The rwi_* drivers were CORBA clients of RWI's Mobility (rwi.md §1): a
// proprietary SDK for Red Hat 6.0 on omniORB 2, which cannot be had or
// built on a current system, and there is no byte protocol an emulator
// could stand in for. Rather than pretend data, each name is refused by the
// server at the configuration's driver name (core::DriverDoc::unavailable),
// with the rflex_* section that drives the same robots' controller.
#include "families/rwi/driver/rwi_drivers.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

struct RwiDriver {
  const char* name;
  std::uint16_t interface;
  protocol::Access access;
  const char* what;
  const char* rflex_section;  // the equivalent, as the rflex sheet gives it
  const char* driven_by;      // who drives that part of the robot instead
  std::vector<std::string> requests;
};

std::string reason(const RwiDriver& driver) {
  return std::string("RWI's Mobility middleware, which ") + driver.name +
         " needs, is proprietary and cannot be had (Player 1.5 built it only against Mobility 1.1.7 for Red Hat 6.0 "
         "on omniORB 2). " + driver.driven_by + ": " + driver.rflex_section +
         " (player-drivers info rflex, docs/compatibility.md \"RWI robots through Mobility\")";
}

core::DriverSpec spec_of(const RwiDriver& driver) {
  core::DriverSpec spec{
      .name = driver.name,
      .interfaces = {driver.interface},
      .access = driver.access,
      // Never reached: the server refuses the section first (doc.unavailable).
      .factory = [name = std::string(driver.name)](const core::DriverContext&) -> std::unique_ptr<core::Driver> {
        throw std::runtime_error(name + " cannot run: RWI's Mobility middleware cannot be had");
      },
      .limits = {},
      .summary = std::string("RWI ") + driver.what +
                 " through Mobility: unavailable (proprietary, unobtainable); use " + driver.rflex_section,
      .family = "rwi",
      .doc = {.manual_section = "7.35",
              .needs_hardware = true,
              .options = {},
              .requests = driver.requests,
              .example = driver.rflex_section,
              .schema = {},
              .unavailable = {}},
  };
  spec.doc.unavailable = reason(driver);
  spec.doc.requests.insert(spec.doc.requests.begin(), "none served: " + reason(driver));
  return spec;
}

}  // namespace

std::vector<core::DriverSpec> rwi_driver_specs() {
  const std::vector<RwiDriver> drivers{
      {"rwi_position", protocol::kPositionCode, protocol::Access::kAll, "B21r/ATRV base (position)",
       "position:0 ( driver \"rflex_position\" rflex_serial_port \"/dev/ttyR0\" mm_length 520 mm_width 520 "
       "odo_distance_conversion 103 odo_angle_conversion 35000 )",
       "The same robots' RFLEX controller is driven directly by the rflex_* drivers",
       {"1.5: MOTOR_POWER, RESET_ODOM, GET_GEOM"}},
      {"rwi_sonar", protocol::kSonarCode, protocol::Access::kRead, "sonar ring (upper or lower array)",
       "sonar:0 ( driver \"rflex_sonar\" num_sonars 24 range_distance_conversion 1.476 )", "The same robots' RFLEX controller is driven directly by the rflex_* drivers", {"1.5: POWER, GET_GEOM"}},
      {"rwi_laser", protocol::kLaserCode, protocol::Access::kRead, "laser through Mobility",
       "laser:0 ( driver \"sicklms200\" port \"/dev/ttyS0\" )",
       "Mobility read the robot's SICK LMS 200, which sicklms200 drives on its own serial line", {"1.5: GET_GEOM"}},
      {"rwi_bumper", protocol::kBumperCode, protocol::Access::kRead, "bump panels",
       "bumper:0 ( driver \"rflex_bumper\" bumper_count 14 )", "The same robots' RFLEX controller is driven directly by the rflex_* drivers", {"1.5: none (GET_GEOM NACKed)"}},
      {"rwi_power", protocol::kPowerCode, protocol::Access::kRead, "battery voltage",
       "power:0 ( driver \"rflex_power\" rflex_power_offset 12 )", "The same robots' RFLEX controller is driven directly by the rflex_* drivers", {"1.5: none (MAIN_POWER NACKed)"}},
  };
  std::vector<core::DriverSpec> specs;
  for (const RwiDriver& driver : drivers) specs.push_back(spec_of(driver));
  return specs;
}

}  // namespace playerkit::drivers
