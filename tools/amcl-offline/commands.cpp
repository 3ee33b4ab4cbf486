#include "commands.hpp"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numbers>
#include <vector>

#include "algorithms/grid/occupancy_grid_builder.hpp"
#include "localization/estimate_writer.hpp"
#include "localization/map_from_log.hpp"
#include "localization/scan_order_matching.hpp"
#include "localization/trajectory.hpp"
#include "localization/trajectory_evaluation.hpp"
#include "log/log_clock_reader.hpp"
#include "log/log_format_detection.hpp"
#include "map/map_file.hpp"
#include "map/trajectory_plot.hpp"
#include "output_file.hpp"

namespace playerkit::amcl_offline {

namespace {


using tools::OutputFile;

}  // namespace

int run_map(const MapOptions& options, std::ostream& err) {
  // Before the work: the map and its .yaml are written only at the end.
  std::filesystem::path yaml(options.output);
  yaml.replace_extension(".yaml");
  tools::refuse_output_over_inputs(options.output, {options.log});
  tools::refuse_output_over_inputs(yaml.string(), {options.log});
  const auto result = localization::map_from_log(options.log, options.mapping, options.reading);
  map::save_map(result.grid, options.output);
  err << "amcl-offline: " << options.output << ": " << result.grid.width() << "x" << result.grid.height()
      << " cells of " << options.mapping.resolution << " m from " << result.scans_used << " scans";
  if (result.scans_skipped_without_pose > 0) err << " (" << result.scans_skipped_without_pose << " without a pose)";
  err << "\n";
  return kExitOk;
}

int run_perturb(const PerturbCommand& command, std::ostream& out, std::ostream& err) {
  OutputFile output(command.output, out, {command.log});
  const auto summary = localization::perturb_log(command.log, output.stream(), command.model, command.seed);
  output.commit();
  err << std::fixed << std::setprecision(2) << "amcl-offline: " << summary.odometry_poses_changed
      << " odometry poses degraded over " << summary.truth_path_m << " m; final drift "
      << summary.final_position_drift_m << " m, " << summary.final_heading_drift_rad / geometry::kRadiansPerDegree << " deg\n";
  return kExitOk;
}

int run_localize(const LocalizeOptions& options, std::ostream& out, std::ostream& err) {
  auto grid = std::make_shared<const grid::OccupancyGrid>(map::load_map(options.map, options.map_loading));

  if (options.plot) tools::refuse_output_over_inputs(*options.plot, {options.log, options.map});
  OutputFile output(options.output, out, {options.log, options.map});
  localization::EstimateWriter writer(output.stream(), options.format);
  std::vector<Eigen::Vector2d> estimated_path;
  std::vector<Eigen::Vector2d> true_path;
  std::vector<Eigen::Vector2d> last_scan;
  std::optional<geometry::Pose2> last_pose;
  std::size_t shown = 0;
  const auto on_scan = [&](const localization::LocalizedScan& row, const localization::LoggedScan& scan) {
    writer.write(row);
    if (options.plot) {
      estimated_path.push_back(row.estimate.mean.translation());
      if (scan.truth) true_path.push_back(scan.truth->translation());
      last_pose = row.estimate.mean;
      last_scan.clear();
      const geometry::Pose2 laser = row.estimate.mean.compose(options.localization.laser_pose);
      for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
        if (!(scan.ranges[i] > 0 && scan.ranges[i] < scan.max_range)) continue;
        const double angle = scan.angle_min + static_cast<double>(i) * scan.angle_increment;
        last_scan.push_back(laser.transform({scan.ranges[i] * std::cos(angle), scan.ranges[i] * std::sin(angle)}));
      }
    }
    if (options.progress && ++shown % 50 == 0) err << "\ramcl-offline: " << shown << " scans" << std::flush;
  };
  const auto summary = localization::localize_log(options.log, grid, options.localization, on_scan);
  if (options.progress) err << "\r\033[K";
  output.commit();
  if (options.plot) {
    std::vector<map::PlotPath> paths;
    if (!true_path.empty()) paths.push_back({true_path, {0, 160, 0}, "truth"});
    paths.push_back({estimated_path, {0, 0, 220}, "amcl"});
    map::write_trajectory_plot(*options.plot, *grid, paths, last_scan, last_pose);
  }
  err << std::fixed << std::setprecision(1) << "amcl-offline: " << summary.scans << " scans ("
      << summary.laser_updates << " updates) in " << std::setprecision(2) << summary.wall_seconds << " s wall";
  if (summary.synthetic_times) {
    err << "; no real-time factor: the log has no usable times\n";
  } else {
    err << ", " << std::setprecision(1) << summary.log_seconds << " s of log: " << std::setprecision(0)
        << summary.real_time_factor() << "x real time\n";
  }
  if (summary.scans_without_odometry > 0) {
    err << "amcl-offline: warning: " << summary.scans_without_odometry << " scans without odometry were skipped\n";
  }
  return kExitOk;
}

int run_eval(const EvalCommand& command, std::ostream& out, std::ostream& err) {
  const auto estimate = localization::read_trajectory_csv(std::filesystem::path(command.estimate));
  localization::Trajectory truth;
  const bool truth_is_csv = std::filesystem::path(command.truth).extension() == ".csv";
  truth = truth_is_csv ? localization::read_trajectory_csv(std::filesystem::path(command.truth))
                       : localization::truth_from_log(command.truth);
  if (truth.empty()) throw std::runtime_error(command.truth + ": no true poses (a log needs truth or corrected poses)");
  // A log without usable times has only file order to pair by.
  const bool by_scan_order = !truth_is_csv && log::audit_log_times(command.truth)->synthetic();
  auto result = localization::evaluate_trajectory(
      by_scan_order ? localization::retimed_by_scan_order(estimate, truth) : estimate, truth);
  result.matched_by_scan_order = by_scan_order;
  if (command.json) {
    out << result.to_json() << "\n";
    return kExitOk;
  }
  const auto row = [&](const char* name, const localization::ErrorStatistics& stats) {
    out << std::left << std::setw(18) << name << std::right << std::fixed << std::setprecision(3) << std::setw(8)
        << stats.position_rmse_m << std::setw(8) << stats.position_max_m << std::setprecision(2) << std::setw(9)
        << stats.heading_rmse_rad / geometry::kRadiansPerDegree << std::setw(9) << stats.heading_max_rad / geometry::kRadiansPerDegree << std::setw(8)
        << stats.count << "\n";
  };
  out << "matched " << result.matched << " of " << result.estimates << " estimates";
  if (by_scan_order) out << " by scan order (" << command.truth << " has no usable times; seconds are file order)";
  out << "\n";
  out << std::left << std::setw(18) << "" << std::right << std::setw(8) << "rmse_m" << std::setw(8) << "max_m"
      << std::setw(9) << "rmse_deg" << std::setw(9) << "max_deg" << std::setw(8) << "rows" << "\n";
  row("all", result.all);
  if (result.converged()) {
    row("after convergence", result.after_convergence);
    out << std::setprecision(1) << "converged after " << *result.convergence_time_s << " s";
    if (result.convergence_distance_m) out << " and " << *result.convergence_distance_m << " m";
    out << "; lost " << result.lost_episodes << " time(s) afterwards";
    if (result.lost_episodes > 0) out << ", the longest for " << result.longest_lost_s << " s";
    out << "\n";
  } else {
    out << "never converged (within " << result.options.converged_position_m << " m and "
        << result.options.converged_heading_rad / geometry::kRadiansPerDegree << " deg)\n";
  }
  (void)err;
  return kExitOk;
}

}  // namespace playerkit::amcl_offline
