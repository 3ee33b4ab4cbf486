#pragma once
// The garminnmea driver's options, declared once (core::OptionSchema), and
// the settings read from a configuration section (garminnmea.md §4).

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::garminnmea {

struct GarminNmeaSettings {
  std::string port = "/dev/ttyS0";
  int baud = 4800;
  bool dgps_enable = true;  // 1.5's default
  std::string dgps_group = "225.0.0.43";
  int dgps_port = 7778;
  std::string dgps_bind = "0.0.0.0";  // where to listen and join
};

[[nodiscard]] const core::OptionSchema& garminnmea_option_schema();

// Throws config::ConfigError at the option's file:line:col.
[[nodiscard]] GarminNmeaSettings read_garminnmea_settings(const config::Section& section);

}  // namespace playerkit::drivers::garminnmea
