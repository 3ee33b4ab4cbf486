#pragma once
// Post-hoc localization: amcl over the scans of a recorded log, one estimate
// per scan (`amcl-offline localize`). The log's odometry moves the filter and
// its scans weigh it, in log order, as fast as the CPU allows.

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "algorithms/amcl/amcl_parameters.hpp"
#include "algorithms/amcl/pose_estimate.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "localization/logged_scan.hpp"
#include "localization/logged_scan_reader.hpp"

namespace playerkit::localization {

struct InitialBelief {
  enum class Kind { pose, first_truth, global };
  Kind kind = Kind::global;
  geometry::Pose2 pose;  // Kind::pose
  // Standard deviations of the initial Gaussian (pose, first_truth).
  double sigma_x_m = 0.1, sigma_y_m = 0.1, sigma_yaw_rad = 0.05;
};

struct OfflineLocalizationOptions {
  amcl::AmclParameters filter;
  InitialBelief initial;
  std::uint64_t seed = 0;
  LoggedScanReaderOptions reader;
  geometry::Pose2 laser_pose;  // the laser in the robot frame (Radish logs: none)
};

// The estimate at one scan's time, whether or not the filter updated on it.
struct LocalizedScan {
  double time = 0;
  amcl::Hypothesis estimate;
  std::size_t particles = 0;
  bool updated = false;  // a laser update ran on this scan
};

struct LocalizationSummary {
  std::size_t scans = 0;
  std::size_t laser_updates = 0;
  std::size_t scans_without_odometry = 0;  // skipped: nothing to move the filter
  std::size_t scans_before_truth = 0;      // first_truth: skipped until a scan had a true pose
  double log_seconds = 0;                  // last scan time - first scan time
  bool synthetic_times = false;            // the log had no usable times: log_seconds is file order
  double wall_seconds = 0;
  // A global start: the particles it drew, and when (seconds into the log)
  // one place had held the belief long enough to end the search.
  std::size_t global_particles = 0;
  std::optional<double> search_ended_at;
  [[nodiscard]] double real_time_factor() const { return wall_seconds > 0 ? log_seconds / wall_seconds : 0; }
};

// Calls `on_scan` for every scan with odometry, in log order, from the first
// one with a true pose for first_truth; `scan` is the logged one (for plots:
// its end points at the estimate). Throws std::runtime_error for an
// unreadable log, std::invalid_argument for an initial belief the log cannot
// give (first_truth and no scan with odometry has a true pose).
LocalizationSummary localize_log(
    const std::filesystem::path& log, std::shared_ptr<const grid::OccupancyGrid> map,
    const OfflineLocalizationOptions& options,
    const std::function<void(const LocalizedScan& result, const LoggedScan& scan)>& on_scan);

}  // namespace playerkit::localization
