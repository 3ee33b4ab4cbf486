#include "families/ptu46/driver/ptu46_options.hpp"

#include <array>
#include <utility>

#include "core/option_reader.hpp"
#include "links/port_option.hpp"

namespace playerkit::drivers::ptu46 {

namespace {

// Linux's termios speed constants up to B38400, by value (asm-generic/termbits.h).
constexpr std::array<std::pair<int, int>, 15> kTermiosSpeeds = {{
    {1, 50}, {2, 75}, {3, 110}, {4, 134}, {5, 150}, {6, 200}, {7, 300}, {8, 600}, {9, 1200},
    {10, 1800}, {11, 2400}, {12, 4800}, {13, 9600}, {14, 19200}, {15, 38400},
}};
constexpr std::array<int, 7> kUnitSpeeds = {600, 1200, 2400, 4800, 9600, 19200, 38400};

}  // namespace

int baud_from_option(int value) {
  for (const int speed : kUnitSpeeds) {
    if (value == speed) return speed;
  }
  for (const auto& [constant, speed] : kTermiosSpeeds) {
    if (value == constant) return speed;
  }
  return 0;
}

const core::OptionSchema& ptu46_option_schema() {
  static const core::OptionSchema schema{
      links::port_option("/dev/ttyR1").doc("the unit's serial port, or tcp:HOST:PORT"),
      core::OptionSpec::integer("baudrate", 9600, 1, 38400)
          .unit("baud")
          .doc("600 to 38400; Player 1.5's termios constants (13 for B9600, 14, 15) are read as their speeds"),
  };
  return schema;
}

Ptu46Settings read_ptu46_settings(const config::Section& section) {
  const core::OptionReader options(section, "ptu46", ptu46_option_schema());
  Ptu46Settings settings;
  settings.port = options.text("port");
  settings.baud = baud_from_option(options.integer("baudrate"));
  if (settings.baud == 0) {
    options.fail({"baudrate"}, "must be 600, 1200, 2400, 4800, 9600, 19200 or 38400 "
                               "(or a termios constant 9 to 15), not " + std::to_string(options.integer("baudrate")));
  }
  return settings;
}

}  // namespace playerkit::drivers::ptu46
