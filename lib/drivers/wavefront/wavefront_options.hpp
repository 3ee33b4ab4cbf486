#pragma once
// wavefront's options (wavefront.md §3, manual §7.47) with the source's and
// the manual's names, and its map, loaded once when the configuration is read
// (an unreadable map is an error at its option's file:line:col).

#include <memory>

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/wavefront/waypoint_follower.hpp"
#include "algorithms/wavefront/wavefront_planner.hpp"
#include "config/config_file.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::wavefront_driver {

struct WavefrontOptions {
  int position_index = 0;
  int localize_index = 0;
  std::shared_ptr<const grid::OccupancyGrid> map;
  wavefront::PlannerParameters planner;
  wavefront::FollowerSettings follower;
  double jump_distance = 0.5;  // m between two localize poses: a jump, plan again
};

const core::OptionSchema& wavefront_option_schema();
// Throws config::ConfigError at the offending value's file:line:col.
WavefrontOptions read_wavefront_options(const config::Section& section);

}  // namespace playerkit::drivers::wavefront_driver
