#pragma once
// The sonyevid30 driver's options (sonyevid30.md §4), declared once
// (core::OptionSchema), and the settings read from a configuration section.

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"
#include "families/sonyevid30/protocol/evid30_units.hpp"

namespace playerkit::drivers::sonyevid30 {

struct Sonyevid30Settings {
  std::string port = "/dev/ttyS2";  // the manual's default
  hardware::sonyevid30::FieldOfView fov;
  // "Movement mode": pan and tilt driven toward the demand instead of sent as absolute targets.
  bool movement = false;
};

[[nodiscard]] const core::OptionSchema& sonyevid30_option_schema();

// Throws config::ConfigError at the option's file:line:col.
[[nodiscard]] Sonyevid30Settings read_sonyevid30_settings(const config::Section& section);

}  // namespace playerkit::drivers::sonyevid30
