#include "localization/map_from_log.hpp"

#include <stdexcept>

namespace playerkit::localization {

MapFromLogResult map_from_log(const std::filesystem::path& log, const grid::OccupancyMappingParameters& parameters,
                              const MapFromLogOptions& options) {
  grid::OccupancyGridBuilder builder(parameters);
  LoggedScanReader reader(log, options.reader);
  MapFromLogResult result;
  const std::size_t stride = options.scan_stride == 0 ? 1 : options.scan_stride;
  std::size_t seen = 0;
  while (seen < options.max_scans) {
    auto scan = reader.next();
    if (!scan) break;
    if (seen++ % stride != 0) continue;
    const auto& pose = scan->truth ? scan->truth
                       : options.use_odometry_without_truth ? scan->odometry
                                                             : std::optional<geometry::Pose2>{};
    if (!pose) {
      ++result.scans_skipped_without_pose;
      continue;
    }
    builder.add_scan(*pose, scan->ranges, scan->angle_min, scan->angle_increment, scan->max_range);
    ++result.scans_used;
  }
  if (result.scans_used == 0) {
    throw std::runtime_error(log.string() + ": no scan with a " +
                             (options.use_odometry_without_truth ? "true or odometry pose" : "true pose") +
                             " to build a map from");
  }
  result.grid = builder.build();
  return result;
}

}  // namespace playerkit::localization
