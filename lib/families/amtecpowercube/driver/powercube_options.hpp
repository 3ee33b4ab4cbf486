#pragma once
// The amtecpowercube driver's options, declared once (core::OptionSchema),
// and the settings read from a configuration section (amtecpowercube.md §4).

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::amtecpowercube {

struct PowercubeSettings {
  std::string port = "/dev/ttyS0";
  bool home_at_shutdown = false;  // `home` != 0
  double speed = 40;              // deg/s
};

[[nodiscard]] const core::OptionSchema& powercube_option_schema();

// Throws config::ConfigError at the option's file:line:col.
[[nodiscard]] PowercubeSettings read_powercube_settings(const config::Section& section);

}  // namespace playerkit::drivers::amtecpowercube
