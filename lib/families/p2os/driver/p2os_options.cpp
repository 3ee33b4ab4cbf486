#include "families/p2os/driver/p2os_options.hpp"

#include <array>
#include <climits>
#include <cmath>
#include <cstddef>

#include "core/option_reader.hpp"
#include "core/robot_option.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::p2os {

namespace {

// Every driver of the family: robot options may sit on any of their sections.
const std::array<std::string_view, kP2osRoleCount>& family_drivers() {
  static const std::array<std::string_view, kP2osRoleCount> names = [] {
    std::array<std::string_view, kP2osRoleCount> all{};
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = driver_name(static_cast<P2osRole>(i));
    return all;
  }();
  return names;
}

core::OptionSchema make_robot_link_schema() {
  using core::OptionSpec;
  return {
      links::port_option(std::string(kDefaultP2osPort))
          .doc("serial port of the robot's HOST connector, or tcp:HOST:PORT; may be written on any one p2os "
               "section of the robot"),
      // 1.5 took any non-zero value as on.
      OptionSpec::integer("radio", 0, INT_MIN, INT_MAX).doc("non-zero: dial a radio modem (WMS2) before connecting"),
      OptionSpec::integer("joystick", 0, INT_MIN, INT_MAX)
          .doc("non-zero: let the robot's joystick drive it (JOYDRIVE 1)"),
      OptionSpec::number("connect_timeout", 5.0, 0.1, 600.0)
          .unit("s")
          .doc("how long setup tries to reach the robot, every speed of 9600, 38400, 19200, 115200, 57600 "
               "(playerkit)"),
      OptionSpec::number("sip_timeout", 2.0, 0.3, 60.0)
          .unit("s")
          .doc("no SIP for this long: the robot counts as gone and is reconnected in the background (playerkit)"),
  };
}

core::OptionSchema make_position_schema() {
  using core::OptionSpec;
  core::OptionSchema schema = robot_link_schema();
  schema.add(OptionSpec::integer("max_xspeed", 500, 0, 10000)
                 .unit("mm/s")
                 .doc("fastest wheel (direct mode; both wheels scale together) or VEL (separate mode)"));
  schema.add(OptionSpec::integer("max_yawspeed", 100, 0, 3600).unit("deg/s").doc("fastest RVEL (separate mode)"));
  schema.add(OptionSpec::integer("use_vel_band", 0, INT_MIN, INT_MAX)
                 .doc("non-zero: never drive the two wheels in opposite directions"));
  return schema;
}

// A robot option read with `read` (an OptionReader member) on every section
// that writes it; they must agree.
template <class Read>
auto robot_value(const core::DriverContext& context, std::string_view name, Read read) {
  return core::robot_value(context, family_drivers(), name,
                           [&](const config::Section& section, const std::string& driver) {
                             return read(core::OptionReader(section, driver, robot_link_schema()), name);
                           });
}

std::chrono::milliseconds seconds_option(const core::DriverContext& context, std::string_view name) {
  const auto value = robot_value(
      context, name, [](const core::OptionReader& options, std::string_view n) { return options.seconds(n); });
  const double fallback = robot_link_schema().find(name)->number_fallback();
  return value.value_or(std::chrono::milliseconds(std::lround(fallback * 1000.0)));
}

bool nonzero_option(const core::DriverContext& context, std::string_view name) {
  const auto value = robot_value(
      context, name, [](const core::OptionReader& options, std::string_view n) { return options.integer(n); });
  return value.value_or(0) != 0;
}

}  // namespace

const core::OptionSchema& robot_link_schema() {
  static const core::OptionSchema schema = make_robot_link_schema();
  return schema;
}

const core::OptionSchema& p2os_option_schema(P2osRole role) {
  static const core::OptionSchema position = make_position_schema();
  return role == P2osRole::position ? position : robot_link_schema();
}

RobotLinkOptions read_robot_link_options(const core::DriverContext& context) {
  RobotLinkOptions options;
  options.port = robot_value(context, "port", [](const core::OptionReader& reader, std::string_view n) {
                   return reader.text(n);
                 }).value_or(std::string(kDefaultP2osPort));
  options.radio = nonzero_option(context, "radio");
  options.joystick = nonzero_option(context, "joystick");
  options.connect_timeout = seconds_option(context, "connect_timeout");
  options.sip_timeout = seconds_option(context, "sip_timeout");
  return options;
}

MotorLimits read_motor_limits(const core::DriverContext& context) {
  const core::OptionReader options(context.section, "p2os_position", p2os_option_schema(P2osRole::position));
  MotorLimits limits;
  limits.max_xspeed = options.integer("max_xspeed");
  limits.max_yawspeed = options.integer("max_yawspeed");
  limits.use_vel_band = options.integer("use_vel_band") != 0;
  return limits;
}

std::string connection_key(const RobotLinkOptions& options) { return "p2os " + options.port; }

}  // namespace playerkit::drivers::p2os
