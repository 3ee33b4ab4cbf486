#pragma once
// The cmucam2 drivers' options, declared once (core::OptionSchema), and the
// settings read from a configuration section. Both devices of one camera
// (blobfinder and ptz) read the same options; the link is keyed by its port.

#include <string>
#include <vector>

#include "config/section.hpp"
#include "core/option_schema.hpp"
#include "families/cmucam2/protocol/cmucam_protocol.hpp"

namespace playerkit::drivers::cmucam2 {

// All blobs go in channel 0, as in 1.5, and a channel holds ten (cmucam2.md §3).
inline constexpr int kMaxColors = 10;

struct Cmucam2Settings {
  std::string port = "/dev/ttyS1";
  std::vector<hardware::cmucam2::ColorBounds> colors{hardware::cmucam2::ColorBounds{16, 16, 16, 16, 16, 16}};
  double degrees_per_position = 0.75;  // of the servos, around position 128
};

[[nodiscard]] const core::OptionSchema& cmucam2_option_schema();

// Throws config::ConfigError at the option's file:line:col.
[[nodiscard]] Cmucam2Settings read_cmucam2_settings(const config::Section& section, const std::string& driver);

}  // namespace playerkit::drivers::cmucam2
