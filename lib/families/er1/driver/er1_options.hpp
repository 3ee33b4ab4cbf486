#pragma once
// The er1_position driver's options (er1.md §4), declared once, and the
// settings read from a configuration section.

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::er1 {

struct Er1Settings {
  std::string port = "/dev/usb/ttyUSB0";  // the source's default; the manual says ttyUSB1
  double axle = 0.38;                     // m between the wheels
  // 1: the left motor on the RCM's motor-0 port; -1: on its motor-1 port.
  int motor_dir = 1;
  bool debug = false;                     // log the odometry once a second
};

[[nodiscard]] const core::OptionSchema& er1_option_schema();

// Throws config::ConfigError at the option's file:line:col.
[[nodiscard]] Er1Settings read_er1_settings(const config::Section& section);

}  // namespace playerkit::drivers::er1
