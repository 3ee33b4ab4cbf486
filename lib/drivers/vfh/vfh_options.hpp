#pragma once
// vfh's options (vfh.md §3, manual §7.45), declared once for the checks,
// `player-drivers info` and the reader, with the names 1.5's source and
// manual both used.

#include "algorithms/vfh/vfh_navigator.hpp"
#include "config/config_file.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::vfh_driver {

struct VfhOptions {
  int position_index = 0;
  int laser_index = 0;
  vfh::NavigatorSettings navigator;
};

const core::OptionSchema& vfh_option_schema();
// Throws config::ConfigError at the offending value's file:line:col.
VfhOptions read_vfh_options(const config::Section& section);

}  // namespace playerkit::drivers::vfh_driver
