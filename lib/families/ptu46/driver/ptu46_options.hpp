#pragma once
// The ptu46 driver's options, declared once (core::OptionSchema), and the
// settings read from a configuration section.

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::ptu46 {

struct Ptu46Settings {
  std::string port = "/dev/ttyR1";  // the reference driver's default (ptu46.md §4)
  int baud = 9600;
};

[[nodiscard]] const core::OptionSchema& ptu46_option_schema();

// Throws config::ConfigError at the option's file:line:col.
[[nodiscard]] Ptu46Settings read_ptu46_settings(const config::Section& section);

// A `baudrate` value as a line speed: a speed (9600), or the value of the
// termios constant Player 1.5's configurations had to give (B9600 = 13 on
// Linux, ptu46.md §1). 0 when it is neither.
[[nodiscard]] int baud_from_option(int value);

}  // namespace playerkit::drivers::ptu46
