#include "families/p2os/driver/p2os_options.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <optional>
#include <vector>

#include "config/errors.hpp"
#include "core/option_reader.hpp"
#include "core/robot_option.hpp"
#include "links/link_address.hpp"
#include "links/link_error.hpp"

namespace playerkit::drivers::p2os {

namespace {

struct RobotSection {
  const config::Section* section;
  std::string driver;
};

// The sections of `context`'s robot (its server port, a p2os driver) that
// write `name`, in config order.
std::vector<RobotSection> robot_sections_with(const core::DriverContext& context, std::string_view name) {
  std::vector<RobotSection> found;
  for (const config::DeviceDeclaration& declaration : context.config.devices()) {
    if (declaration.port != context.key.port) continue;
    if (std::find(kP2osDriverNames.begin(), kP2osDriverNames.end(), declaration.driver) ==
        kP2osDriverNames.end()) {
      continue;
    }
    const config::Section& section = context.config.section(declaration.section);
    if (section.has(name)) found.push_back({&section, declaration.driver});
  }
  return found;
}

// A robot option read with `read` (an OptionReader member) on every section
// that writes it; they must agree.
template <class Value, class Read>
Value robot_value(const core::DriverContext& context, std::string_view name, Value fallback, Read read) {
  std::optional<Value> value;
  std::optional<config::SourceLocation> first;
  for (const RobotSection& place : robot_sections_with(context, name)) {
    const core::OptionReader options(*place.section, place.driver);
    const Value here = read(options, name);
    if (!value) {
      value = here;
      first = options.where({name});
    } else if (!(here == *value)) {
      options.fail({name}, "differs from the value given at " + config::to_string(*first) +
                               "; the devices of one robot share one connection");
    }
  }
  return value.value_or(fallback);
}

std::chrono::milliseconds seconds_option(const core::DriverContext& context, std::string_view name,
                                         double fallback, double minimum, double maximum) {
  const double seconds = robot_value<double>(
      context, name, fallback, [&](const core::OptionReader& options, std::string_view n) {
        return options.number({n}, fallback, minimum, maximum);
      });
  return std::chrono::milliseconds(std::lround(seconds * 1000.0));
}

bool nonzero_option(const core::DriverContext& context, std::string_view name) {
  return robot_value<int>(context, name, 0, [](const core::OptionReader& options, std::string_view n) {
           return options.integer({n}, 0, INT_MIN, INT_MAX);
         }) != 0;
}

}  // namespace

RobotLinkOptions read_robot_link_options(const core::DriverContext& context) {
  RobotLinkOptions options;
  const core::RobotOption port = core::robot_option(
      context,
      {kP2osDriverNames[0], kP2osDriverNames[1], kP2osDriverNames[2], kP2osDriverNames[3],
       kP2osDriverNames[4], kP2osDriverNames[5], kP2osDriverNames[6], kP2osDriverNames[7],
       kP2osDriverNames[8], kP2osDriverNames[9], kP2osDriverNames[10]},
      "port", kDefaultP2osPort);
  options.port = port.value;
  if (port.given) {
    // A malformed tcp: address is a config error, not a failed subscription.
    const RobotSection place = robot_sections_with(context, "port").front();
    const core::OptionReader reader(*place.section, place.driver);
    if (options.port.empty()) reader.fail({"port"}, "must not be empty");
    try {
      (void)links::parse_link_address(options.port);
    } catch (const links::LinkError& e) {
      reader.fail({"port"}, std::string("is not a serial port or tcp:HOST:PORT: ") + e.what());
    }
  }
  options.radio = nonzero_option(context, "radio");
  options.joystick = nonzero_option(context, "joystick");
  options.connect_timeout = seconds_option(context, "connect_timeout", 5.0, 0.1, 600.0);
  options.sip_timeout = seconds_option(context, "sip_timeout", 2.0, 0.3, 60.0);
  return options;
}

MotorLimits read_motor_limits(const core::DriverContext& context) {
  const core::OptionReader options(context.section, "p2os_position");
  MotorLimits limits;
  limits.max_xspeed = options.integer({"max_xspeed"}, 500, 0, 10000);
  limits.max_yawspeed = options.integer({"max_yawspeed"}, 100, 0, 3600);
  limits.use_vel_band = options.integer({"use_vel_band"}, 0, INT_MIN, INT_MAX) != 0;
  return limits;
}

std::string connection_key(const RobotLinkOptions& options) { return "p2os " + options.port; }

}  // namespace playerkit::drivers::p2os
