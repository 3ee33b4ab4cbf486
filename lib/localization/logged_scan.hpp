#pragma once
// One laser scan of a log with the poses that belong to it: the input of
// post-hoc localization (amcl-offline) and of maps built from logs.

#include <optional>
#include <vector>

#include "algorithms/geometry/pose2.hpp"

namespace playerkit::localization {

struct LoggedScan {
  double time = 0;              // the scan's data timestamp, s
  std::vector<double> ranges;   // m, beam i at angle_min + i * angle_increment
  double angle_min = 0;         // rad, laser frame, counter-clockwise
  double angle_increment = 0;   // rad
  double max_range = 0;         // m; readings >= max_range are no-return
  std::optional<geometry::Pose2> odometry;  // robot pose by odometry at scan time
  std::optional<geometry::Pose2> truth;     // true laser pose at scan time, if the log has one
};

}  // namespace playerkit::localization
