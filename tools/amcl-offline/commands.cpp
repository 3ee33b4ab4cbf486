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
#include "localization/uncertain_stretches.hpp"
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
  // Warnings come after the summary: a progress line may be showing.
  localization::UncertaintyWatch watch;
  std::vector<localization::UncertainStretch> unsure;
  const auto on_scan = [&](const localization::LocalizedScan& row, const localization::LoggedScan& scan) {
    writer.write(row);
    if (auto ended = watch.observe(row.time, row.estimate.covariance)) unsure.push_back(*ended);
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
  if (summary.global_particles > 0) {
    const auto& filter = options.localization.filter;
    err << std::fixed << std::setprecision(0) << "amcl-offline: global start: " << summary.global_particles
        << " particles (" << filter.global_particles_per_square_metre << " per m^2 of free space, "
        << filter.max_particles << " to " << filter.global_particles_most << "); ";
    if (summary.search_ended_at) {
      err << std::setprecision(1) << "found after " << *summary.search_ended_at << " s of log (one place held "
          << std::setprecision(0) << 100 * filter.search_end_weight << " % of the belief for "
          << filter.search_end_updates << " updates)\n";
    } else {
      err << "the search never settled on one place\n";
    }
  }
  err << std::fixed << std::setprecision(1) << "amcl-offline: " << summary.scans << " scans ("
      << summary.laser_updates << " updates) in " << std::setprecision(2) << summary.wall_seconds << " s wall";
  if (summary.synthetic_times) {
    err << "; no real-time factor: the log has no usable times\n";
  } else if (!(summary.log_seconds > 0)) {
    err << "; no real-time factor: the scans span no time\n";
  } else {
    err << ", " << std::setprecision(1) << summary.log_seconds << " s of log: " << std::setprecision(0)
        << summary.real_time_factor() << "x real time\n";
  }
  if (summary.scans_before_truth > 0) {
    err << "amcl-offline: warning: started at the first scan with a true pose; "
        << summary.scans_before_truth << (summary.scans_before_truth == 1 ? " scan" : " scans")
        << " before it skipped\n";
  }
  if (summary.scans_without_odometry > 0) {
    err << "amcl-offline: warning: " << summary.scans_without_odometry << " scans without odometry were skipped\n";
  }
  if (auto last = watch.finish()) unsure.push_back(*last);
  for (const auto& stretch : unsure) {
    err << std::fixed << std::setprecision(1) << "amcl-offline: warning: lost (its own 2-sigma past 1 m or 60 deg) from " << stretch.start_time
        << " s to " << stretch.end_time << " s (" << stretch.rows << (stretch.rows == 1 ? " scan" : " scans")
        << "): 2-sigma up to " << std::setprecision(2) << stretch.worst_position_2sigma_m << " m and "
        << std::setprecision(0) << stretch.worst_heading_2sigma_rad / geometry::kRadiansPerDegree << " deg\n";
  }
  return kExitOk;
}


}  // namespace playerkit::amcl_offline
