#pragma once
// The trogdor driver's options (trogdor.md §4), declared once.

#include <string>

#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::trogdor {

// The reference driver's default port (its shipped configuration says /dev/usb/tts/0).
inline constexpr const char* kDefaultPort = "/dev/usb/ttyUSB1";

[[nodiscard]] const core::OptionSchema& trogdor_option_schema();

// The port; throws config::ConfigError at the option's file:line:col.
[[nodiscard]] std::string read_trogdor_port(const config::Section& section);

}  // namespace playerkit::drivers::trogdor
