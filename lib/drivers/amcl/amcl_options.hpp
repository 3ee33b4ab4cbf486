#pragma once
// The `amcl` driver's configuration-file options (manual 7.3, Player 1.5's
// real key names, and the newer tunables under ROS amcl's names), read into
// what the driver needs. README.md lists every option with its default.

#include <cstdint>
#include <memory>
#include <optional>

#include "algorithms/amcl/amcl_filter.hpp"
#include "algorithms/amcl/amcl_parameters.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "config/section.hpp"

namespace playerkit::drivers {

struct AmclOptions {
  int position_index = 0;
  int laser_index = 0;
  std::shared_ptr<const grid::OccupancyGrid> map;
  amcl::AmclParameters parameters;
  geometry::Pose2 laser_pose;    // laser in the robot frame
  double laser_range_max = 8.0;  // m; readings at or beyond it are "no return"
  // Empty: start spread uniformly over the free space (global localization).
  std::optional<amcl::StartPose> initial_pose;
  std::uint64_t seed = 0;
};

// Reads and checks every option; loads the map. Throws config::ConfigError at
// the offending option (or the section when the filter rejects a combination).
AmclOptions read_amcl_options(const config::Section& section);

}  // namespace playerkit::drivers
