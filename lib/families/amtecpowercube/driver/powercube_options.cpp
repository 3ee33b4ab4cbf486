#include "families/amtecpowercube/driver/powercube_options.hpp"

#include <limits>

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::amtecpowercube {

const core::OptionSchema& powercube_option_schema() {
  static const core::OptionSchema schema{
      links::port_option("/dev/ttyS0").doc("the wrist's serial port (38400 baud), or tcp:HOST:PORT"),
      // 1.5 read any integer and tested it against 0: its files may say `home 2`.
      core::OptionSpec::integer("home", 0, std::numeric_limits<int>::min(), std::numeric_limits<int>::max())
          .doc("not 0: home both modules again at shutdown (they are always homed at start-up)"),
      core::OptionSpec::number("speed", 40, 0.1, 1000)
          .unit("deg/s")
          .doc("top pan and tilt speed: position moves are timed for it, velocity demands limited to it"),
  };
  return schema;
}

PowercubeSettings read_powercube_settings(const config::Section& section) {
  const core::OptionReader options(section, "amtecpowercube", powercube_option_schema());
  PowercubeSettings settings;
  settings.port = options.text("port");
  settings.home_at_shutdown = options.integer("home") != 0;
  settings.speed = options.number("speed");
  return settings;
}

}  // namespace playerkit::drivers::amtecpowercube
