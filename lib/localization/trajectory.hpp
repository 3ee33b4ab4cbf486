#pragma once
// Timed 2-D poses: what a localizer estimates and what it is judged against.
//
//   auto estimate = localization::read_trajectory_csv("estimate.csv");
//   auto truth = localization::truth_from_log("intel-corrected.log.gz");
//
// CSV: a header line naming at least the columns time, x, y, yaw (any order;
// other columns are ignored), then one row per pose: s, m, m, rad. Blank lines
// and lines starting with '#' are skipped. With std_x, std_y and std_yaw
// columns too (localize's), each pose carries its spread, cov_xy 0 when
// there is no such column (older estimates).

#include <filesystem>
#include <istream>
#include <optional>
#include <ostream>
#include <string_view>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "localization/logged_scan_reader.hpp"

namespace playerkit::localization {

// The uncertainty an estimate claims (m^2, m^2, m^2, rad^2).
struct PoseSpread {
  double var_x = 0, var_y = 0, cov_xy = 0, var_yaw = 0;
};

struct TimedPose {
  TimedPose() = default;
  // A constructor rather than an aggregate, so {time, pose} needs no spread.
  TimedPose(double time_s, const geometry::Pose2& at, std::optional<PoseSpread> claimed = std::nullopt)
      : time(time_s), pose(at), spread(claimed) {}

  double time = 0;  // s
  geometry::Pose2 pose;
  std::optional<PoseSpread> spread;  // an estimate's, when its CSV has std_x, std_y, std_yaw
};

using Trajectory = std::vector<TimedPose>;

// Throws std::runtime_error "name:line: message" for a missing header column,
// a row with too few fields or a field that is not a finite number.
Trajectory read_trajectory_csv(std::istream& in, std::string_view name);
// The same from a file (plain text); throws std::runtime_error when unreadable.
Trajectory read_trajectory_csv(const std::filesystem::path& path);

// "time,x,y,yaw" and one row per pose (9 decimals: nanoseconds, nanometres).
void write_trajectory_csv(std::ostream& out, const Trajectory& trajectory);

// The true poses of a log: in a Player log with usable times, every truth
// sample (truth:<laser_index>) at its own time, in time order, so an estimate
// is judged against the truth of its moment even where a recording lost the
// sample of a scan's time; otherwise (CARMEN, a log without usable times,
// whose estimates are matched by scan order) the scans' true poses at the
// scans' times, scans without truth left out. Throws what LoggedScanReader
// throws.
Trajectory truth_from_log(const std::filesystem::path& log, LoggedScanReaderOptions options = {});

}  // namespace playerkit::localization
