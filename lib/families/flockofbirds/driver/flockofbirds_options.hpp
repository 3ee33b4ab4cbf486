#pragma once
// The flockofbirds driver's options, declared once (core::OptionSchema),
// and the settings read from a configuration section.

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::flockofbirds {

struct FlockSettings {
  std::string port = "/dev/ttyS0";  // the reference driver's default (flockofbirds.md §4)
  int baud = 115200;
};

[[nodiscard]] const core::OptionSchema& flockofbirds_option_schema();

// Throws config::ConfigError at the option's file:line:col.
[[nodiscard]] FlockSettings read_flockofbirds_settings(const config::Section& section);

// A `baudrate` value as a line speed the bird has (2400 to 115200), or the
// value of the termios constant Player 1.5's configurations had to give
// (B115200 = 4098, B9600 = 13 on Linux, flockofbirds.md §1). 0 when neither.
[[nodiscard]] int baud_from_option(int value);

}  // namespace playerkit::drivers::flockofbirds
