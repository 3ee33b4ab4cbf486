#include "families/reb/driver/reb_options.hpp"

#include <array>

#include "core/option_reader.hpp"
#include "core/robot_option.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::reb {

namespace {

constexpr std::array<std::string_view, 3> kFamilyDrivers = {"reb_position", "reb_ir", "reb_power"};

core::OptionSchema make_robot_schema() {
  return {
      links::port_option(std::string(kDefaultRebPort))
          .doc("serial port of the board (38400 baud, 8N2), or tcp:HOST:PORT; may be written on any one reb "
               "section of the robot"),
      core::OptionSpec::text("subclass", "slow")
          .doc("the UBot's encoders: \"fast\" (7.92 pulses/mm) or \"slow\" (24.33 pulses/mm; anything else)"),
  };
}

core::OptionSchema make_position_schema() {
  core::OptionSchema schema = make_robot_schema();
  schema.add(core::OptionSpec::integer("heading_control", 0, 0, 1)
                 .doc("1: start in 1.5's heading control (VELOCITY_MODE 1: turn towards the commanded yaw, "
                      "yawspeed the gain); 0: velocities as commanded (playerkit)"));
  return schema;
}

const core::OptionSchema& robot_schema() {
  static const core::OptionSchema schema = make_robot_schema();
  return schema;
}

template <class Read>
auto robot_value(const core::DriverContext& context, std::string_view name, Read read) {
  return core::robot_value(context, kFamilyDrivers, name,
                           [&](const config::Section& section, const std::string& driver) {
                             return read(core::OptionReader(section, driver, robot_schema()), name);
                           });
}

}  // namespace

std::string_view driver_name(RebRole role) { return kFamilyDrivers[static_cast<std::size_t>(role)]; }

const core::OptionSchema& reb_option_schema(RebRole role) {
  static const core::OptionSchema position = make_position_schema();
  return role == RebRole::position ? position : robot_schema();
}

RebLinkOptions read_reb_link_options(const core::DriverContext& context) {
  const auto text = [](const core::OptionReader& reader, std::string_view name) { return reader.text(name); };
  RebLinkOptions options;
  options.port = robot_value(context, "port", text).value_or(std::string(kDefaultRebPort));
  options.subclass = robot_value(context, "subclass", text).value_or("slow");
  return options;
}

bool read_heading_control(const core::DriverContext& context) {
  const core::OptionReader options(context.section, "reb_position", reb_option_schema(RebRole::position));
  return options.integer("heading_control") != 0;
}

std::string connection_key(const RebLinkOptions& options) { return "reb " + options.port; }

}  // namespace playerkit::drivers::reb
