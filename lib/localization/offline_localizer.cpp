#include "localization/offline_localizer.hpp"

#include <chrono>
#include <optional>
#include <stdexcept>
#include <utility>

#include "algorithms/amcl/amcl_filter.hpp"
#include "algorithms/amcl/laser_scan.hpp"

namespace playerkit::localization {

namespace {

amcl::LaserScan to_filter_scan(const LoggedScan& logged, const geometry::Pose2& laser_pose) {
  amcl::LaserScan scan;
  scan.ranges = logged.ranges;
  scan.bearings.resize(logged.ranges.size());
  for (std::size_t i = 0; i < scan.bearings.size(); ++i) {
    scan.bearings[i] = logged.angle_min + static_cast<double>(i) * logged.angle_increment;
  }
  scan.max_range = logged.max_range;
  scan.sensor_pose = laser_pose;
  return scan;
}

Eigen::Matrix3d diagonal_covariance(const InitialBelief& belief) {
  return Eigen::Vector3d(belief.sigma_x_m * belief.sigma_x_m, belief.sigma_y_m * belief.sigma_y_m,
                         belief.sigma_yaw_rad * belief.sigma_yaw_rad)
      .asDiagonal();
}

}  // namespace

LocalizationSummary localize_log(
    const std::filesystem::path& log, std::shared_ptr<const grid::OccupancyGrid> map,
    const OfflineLocalizationOptions& options,
    const std::function<void(const LocalizedScan& result, const LoggedScan& scan)>& on_scan) {
  const auto wall_start = std::chrono::steady_clock::now();
  LoggedScanReader reader(log, options.reader);
  const Eigen::Matrix3d initial_covariance = diagonal_covariance(options.initial);
  // The filter draws its particles once, where it starts: at a pose, or over
  // the whole map, or (first_truth) at the first scan's true pose.
  std::optional<amcl::AmclFilter> filter;
  const auto start_filter = [&](const std::optional<amcl::StartPose>& start) {
    filter.emplace(options.filter, map, options.seed, start);
  };
  switch (options.initial.kind) {
    case InitialBelief::Kind::pose:
      start_filter(amcl::StartPose{options.initial.pose, initial_covariance});
      break;
    case InitialBelief::Kind::global:
      start_filter(std::nullopt);
      break;
    case InitialBelief::Kind::first_truth:
      break;  // at the first scan
  }

  LocalizationSummary summary;
  if (options.initial.kind == InitialBelief::Kind::global) summary.global_particles = filter->particles().size();
  std::optional<double> first_time;
  while (auto logged = reader.next()) {
    if (!logged->odometry) continue;  // counted by the reader
    if (!filter) {
      // A recorder may keep a scan or two before the truth device's first
      // sample: the run starts at the first scan that has one.
      if (!logged->truth) {
        ++summary.scans_before_truth;
        continue;
      }
      // The truth is the laser's pose; the filter tracks the robot's.
      start_filter(amcl::StartPose{logged->truth->compose(options.laser_pose.inverse()), initial_covariance});
    }
    const amcl::LaserScan scan = to_filter_scan(*logged, options.laser_pose);
    LocalizedScan result;
    result.time = logged->time;
    result.updated = filter->update(*logged->odometry, &scan);
    // Between updates the particles stay where they last moved: carry the
    // estimate to this scan's odometry.
    result.estimate = filter->predict(*logged->odometry);
    result.particles = filter->particles().size();
    if (!first_time) first_time = logged->time;
    summary.log_seconds = logged->time - *first_time;
    if (summary.global_particles > 0 && !summary.search_ended_at && !filter->searching()) {
      summary.search_ended_at = summary.log_seconds;
    }
    ++summary.scans;
    if (result.updated) ++summary.laser_updates;
    on_scan(result, *logged);
  }
  if (!filter) {
    throw std::invalid_argument(log.string() + ": no scan with odometry has a true pose to start from");
  }
  summary.scans_without_odometry = reader.scans_without_odometry();
  summary.synthetic_times = reader.clock().synthetic();
  summary.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return summary;
}

}  // namespace playerkit::localization
