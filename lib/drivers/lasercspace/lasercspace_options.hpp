#pragma once
// lasercspace's options (lasercspace.md §3), declared once for the checks,
// `player-drivers info` and the reader.

#include "config/config_file.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::lasercspace {

struct LaserCspaceOptions {
  int laser_index = 0;       // the source laser, on the same port
  double radius = 0.5;       // metres: the robot's
  int obstacle_stride = 1;   // 1.5's `step`: every how-many-th return is an obstacle
};

const core::OptionSchema& lasercspace_option_schema();
// Throws config::ConfigError at the offending value's file:line:col.
LaserCspaceOptions read_lasercspace_options(const config::Section& section);

}  // namespace playerkit::drivers::lasercspace
