#include "families/flockofbirds/driver/flockofbirds_options.hpp"

#include <array>
#include <utility>

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::flockofbirds {

namespace {

// The bird's speeds (its dip switches) and Linux's termios constants for
// them, by value (asm-generic/termbits.h: B57600 and B115200 are 0010001 and
// 0010002 octal).
constexpr std::array<std::pair<int, int>, 7> kTermiosSpeeds = {{
    {11, 2400}, {12, 4800}, {13, 9600}, {14, 19200}, {15, 38400}, {4097, 57600}, {4098, 115200},
}};

}  // namespace

int baud_from_option(int value) {
  for (const auto& [constant, speed] : kTermiosSpeeds) {
    if (value == speed || value == constant) return speed;
  }
  return 0;
}

const core::OptionSchema& flockofbirds_option_schema() {
  static const core::OptionSchema schema{
      links::port_option("/dev/ttyS0").doc("the bird's serial port, or tcp:HOST:PORT"),
      core::OptionSpec::integer("baudrate", 115200, 1, 115200)
          .unit("baud")
          .doc("2400 to 115200; Player 1.5's termios constants (4098 for B115200, 13 for B9600, ...) are read as "
               "their speeds"),
  };
  return schema;
}

FlockSettings read_flockofbirds_settings(const config::Section& section) {
  const core::OptionReader options(section, "flockofbirds", flockofbirds_option_schema());
  FlockSettings settings;
  settings.port = options.text("port");
  settings.baud = baud_from_option(options.integer("baudrate"));
  if (settings.baud == 0) {
    options.fail({"baudrate"}, "must be 2400, 4800, 9600, 19200, 38400, 57600 or 115200 (or a termios constant: "
                               "11 to 15, 4097, 4098), not " + std::to_string(options.integer("baudrate")));
  }
  return settings;
}

}  // namespace playerkit::drivers::flockofbirds
