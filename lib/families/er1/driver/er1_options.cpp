#include "families/er1/driver/er1_options.hpp"

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::er1 {

const core::OptionSchema& er1_option_schema() {
  static const core::OptionSchema schema{
      links::port_option("/dev/usb/ttyUSB0").doc("the Robot Control Module's USB-serial port (230400 baud), or tcp:HOST:PORT"),
      core::OptionSpec::number("axle", 0.38, 0.05, 5.0).unit("m").doc("distance between the drive wheels"),
      core::OptionSpec::choice("motor_dir", 1, {-1, 1})
          .doc("which port the left motor is on: 1 the RCM's motor-0 port, -1 its motor-1 port"),
      core::OptionSpec::integer("debug", 0, 0, 1).doc("1: log the odometry once a second"),
  };
  return schema;
}

Er1Settings read_er1_settings(const config::Section& section) {
  const core::OptionReader options(section, "er1_position", er1_option_schema());
  return {.port = options.text("port"),
          .axle = options.number("axle"),
          .motor_dir = options.integer("motor_dir"),
          .debug = options.integer("debug") != 0};
}

}  // namespace playerkit::drivers::er1
