#pragma once
// An occupancy grid from the scans of a log whose poses are right: Radish's
// SLAM-corrected logs, or any log with truth lines.
//
//   auto grid = localization::map_from_log("intel-corrected.log.gz", {.resolution = 0.05}, {});
//
// Each scan goes into grid::OccupancyGridBuilder at its true laser pose; a log
// without truth can use odometry instead (use_odometry_without_truth), which
// only makes a good map when the odometry is good.

#include <cstddef>
#include <filesystem>
#include <limits>

#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/occupancy_grid_builder.hpp"
#include "localization/logged_scan_reader.hpp"

namespace playerkit::localization {

struct MapFromLogOptions {
  LoggedScanReaderOptions reader;
  bool use_odometry_without_truth = false;
  // Only every n-th scan (1 = all): a coarse map of a long log, faster.
  std::size_t scan_stride = 1;
  // At most this many scans (counted before the stride).
  std::size_t max_scans = std::numeric_limits<std::size_t>::max();
};

struct MapFromLogResult {
  grid::OccupancyGrid grid;
  std::size_t scans_used = 0;
  std::size_t scans_skipped_without_pose = 0;
};

// Throws std::runtime_error when the log is unreadable or no scan has a usable
// pose, and what the builder throws for bad parameters.
MapFromLogResult map_from_log(const std::filesystem::path& log, const grid::OccupancyMappingParameters& parameters,
                              const MapFromLogOptions& options = {});

}  // namespace playerkit::localization
