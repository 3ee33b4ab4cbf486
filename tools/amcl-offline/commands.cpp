#include "commands.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <vector>

#include "algorithms/grid/occupancy_grid_builder.hpp"
#include "localization/estimate_writer.hpp"
#include "localization/map_from_log.hpp"
#include "localization/trajectory.hpp"
#include "localization/trajectory_evaluation.hpp"
#include "log/log_format_detection.hpp"
#include "map/map_file.hpp"
#include "map/trajectory_plot.hpp"
#include "output_file.hpp"

namespace playerkit::amcl_offline {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

std::vector<double> parse_numbers(const std::string& text, std::size_t count, const std::string& what) {
  std::vector<double> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    double value = 0;
    const char* first = item.data();
    const char* last = item.data() + item.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || !std::isfinite(value)) {
      throw UsageError(what + ": '" + item + "' is not a number");
    }
    values.push_back(value);
  }
  if (values.size() != count) {
    throw UsageError(what + ": expected " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
  }
  return values;
}

using tools::OutputFile;

localization::OfflineLocalizationOptions localization_options(const LocalizeCommand& command) {
  localization::OfflineLocalizationOptions options;
  options.seed = command.seed;
  if (command.model == "likelihood" || command.model == "likelihood_field") {
    options.filter.laser_model = amcl::LaserModelType::likelihood_field;
  } else if (command.model == "beam") {
    options.filter.laser_model = amcl::LaserModelType::beam;
  } else {
    throw UsageError("--model: '" + command.model + "' is not beam or likelihood");
  }
  if (command.laser_beams) {
    if (*command.laser_beams < 1) throw UsageError("--laser-beams must be at least 1");
    options.filter.laser_max_beams = *command.laser_beams;
  }
  if (command.particles) {
    const auto bounds = parse_numbers(*command.particles, 2, "--particles");
    if (bounds[0] < 1 || bounds[1] < bounds[0] || bounds[0] != std::floor(bounds[0]) ||
        bounds[1] != std::floor(bounds[1])) {
      throw UsageError("--particles: MIN,MAX with 1 <= MIN <= MAX, whole numbers");
    }
    options.filter.min_particles = static_cast<std::size_t>(bounds[0]);
    options.filter.max_particles = static_cast<std::size_t>(bounds[1]);
  }
  if (command.alpha_slow) options.filter.alpha_slow = *command.alpha_slow;
  if (command.alpha_fast) options.filter.alpha_fast = *command.alpha_fast;
  if (options.filter.alpha_slow < 0 || options.filter.alpha_fast < 0 ||
      (options.filter.alpha_slow > 0 && options.filter.alpha_fast <= options.filter.alpha_slow)) {
    throw UsageError("--alpha-slow/--alpha-fast: 0 <= slow < fast (or both 0 for no recovery)");
  }
  if (command.odom_noise_scale) {
    if (!(*command.odom_noise_scale > 0)) throw UsageError("--odom-noise must be > 0");
    auto& f = options.filter;
    f.rotation_noise_from_rotation *= *command.odom_noise_scale;
    f.rotation_noise_from_translation *= *command.odom_noise_scale;
    f.translation_noise_from_translation *= *command.odom_noise_scale;
    f.translation_noise_from_rotation *= *command.odom_noise_scale;
    f.strafe_noise_from_translation *= *command.odom_noise_scale;
  }
  if (command.update_thresh) {
    const auto thresholds = parse_numbers(*command.update_thresh, 2, "--update-thresh");
    if (thresholds[0] < 0 || thresholds[1] < 0) throw UsageError("--update-thresh: D,A_DEG, both >= 0");
    options.filter.update_min_distance = thresholds[0];
    options.filter.update_min_angle = thresholds[1] * kDegree;
  }
  if (command.sigma_hit) {
    if (!(*command.sigma_hit > 0)) throw UsageError("--sigma-hit must be > 0");
    options.filter.sigma_hit = *command.sigma_hit;
  }
  if (command.global && command.init_pose) throw UsageError("--global and --init-pose exclude each other");
  if (command.init_var) {
    const auto sigma = parse_numbers(*command.init_var, 3, "--init-var");
    if (sigma[0] <= 0 || sigma[1] <= 0 || sigma[2] <= 0) throw UsageError("--init-var: every deviation must be > 0");
    options.initial.sigma_x_m = sigma[0];
    options.initial.sigma_y_m = sigma[1];
    options.initial.sigma_yaw_rad = sigma[2] * kDegree;
  }
  if (command.global) {
    options.initial.kind = localization::InitialBelief::Kind::global;
  } else if (!command.init_pose) {
    throw UsageError("say where the robot starts: --init-pose X,Y,YAW_DEG, --init-pose truth, or --global");
  } else if (*command.init_pose == "truth") {
    options.initial.kind = localization::InitialBelief::Kind::first_truth;
  } else {
    const auto pose = parse_numbers(*command.init_pose, 3, "--init-pose");
    options.initial.kind = localization::InitialBelief::Kind::pose;
    options.initial.pose = {pose[0], pose[1], geometry::normalize_angle(pose[2] * kDegree)};
  }
  return options;
}

}  // namespace

int run_map(const MapCommand& command, std::ostream& err) {
  if (!(command.resolution > 0)) throw UsageError("--resolution must be > 0");
  if (!(command.max_range > 0)) throw UsageError("--max-range must be > 0");
  if (!(command.no_return_clears >= 0)) throw UsageError("--no-return-clears must be >= 0");
  grid::OccupancyMappingParameters parameters;
  parameters.resolution = command.resolution;
  parameters.max_usable_range = command.max_range;
  parameters.no_return_clear_range = command.no_return_clears;
  localization::MapFromLogOptions options;
  options.use_odometry_without_truth = command.use_odometry;
  const auto result = localization::map_from_log(command.log, parameters, options);
  map::save_map(result.grid, command.output);
  err << "amcl-offline: " << command.output << ": " << result.grid.width() << "x" << result.grid.height()
      << " cells of " << command.resolution << " m from " << result.scans_used << " scans";
  if (result.scans_skipped_without_pose > 0) err << " (" << result.scans_skipped_without_pose << " without a pose)";
  err << "\n";
  return kExitOk;
}

int run_perturb(const PerturbCommand& command, std::ostream& out, std::ostream& err) {
  OutputFile output(command.output, out);
  const auto summary = localization::perturb_log(command.log, output.stream(), command.model, command.seed);
  output.flush();
  err << std::fixed << std::setprecision(2) << "amcl-offline: " << summary.odometry_poses_changed
      << " odometry poses degraded over " << summary.truth_path_m << " m; final drift "
      << summary.final_position_drift_m << " m, " << summary.final_heading_drift_rad / kDegree << " deg\n";
  return kExitOk;
}

int run_localize(const LocalizeCommand& command, std::ostream& out, std::ostream& err) {
  auto options = localization_options(command);
  localization::EstimateFormat format = localization::EstimateFormat::csv;
  if (command.format == "json") format = localization::EstimateFormat::json;
  else if (command.format == "log") format = localization::EstimateFormat::player_log;
  else if (command.format != "csv") throw UsageError("--format: '" + command.format + "' is not csv, json or log");

  map::MapLoadOptions map_options;
  map_options.resolution = command.scale;
  map_options.negate = command.negate;
  auto grid = std::make_shared<const grid::OccupancyGrid>(map::load_map(command.map, map_options));

  OutputFile output(command.output, out);
  localization::EstimateWriter writer(output.stream(), format);
  std::vector<Eigen::Vector2d> estimated_path;
  std::vector<Eigen::Vector2d> true_path;
  std::vector<Eigen::Vector2d> last_scan;
  std::optional<geometry::Pose2> last_pose;
  std::size_t shown = 0;
  const auto summary = localization::localize_log(
      command.log, grid, options, [&](const localization::LocalizedScan& row, const localization::LoggedScan& scan) {
        writer.write(row);
        if (command.plot) {
          estimated_path.push_back(row.estimate.mean.translation());
          if (scan.truth) true_path.push_back(scan.truth->translation());
          last_pose = row.estimate.mean;
          last_scan.clear();
          const geometry::Pose2 laser = row.estimate.mean.compose(options.laser_pose);
          for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
            if (!(scan.ranges[i] > 0 && scan.ranges[i] < scan.max_range)) continue;
            const double angle = scan.angle_min + static_cast<double>(i) * scan.angle_increment;
            last_scan.push_back(laser.transform({scan.ranges[i] * std::cos(angle), scan.ranges[i] * std::sin(angle)}));
          }
        }
        if (command.progress && ++shown % 50 == 0) err << "\ramcl-offline: " << shown << " scans" << std::flush;
      });
  if (command.progress) err << "\r\033[K";
  output.flush();
  if (command.plot) {
    std::vector<map::PlotPath> paths;
    if (!true_path.empty()) paths.push_back({true_path, {0, 160, 0}, "truth"});
    paths.push_back({estimated_path, {0, 0, 220}, "amcl"});
    map::write_trajectory_plot(*command.plot, *grid, paths, last_scan, last_pose);
  }
  err << std::fixed << std::setprecision(1) << "amcl-offline: " << summary.scans << " scans ("
      << summary.laser_updates << " updates) in " << std::setprecision(2) << summary.wall_seconds << " s wall, "
      << std::setprecision(1) << summary.log_seconds << " s of log: " << std::setprecision(0)
      << summary.real_time_factor() << "x real time\n";
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
  const auto result = localization::evaluate_trajectory(estimate, truth);
  if (command.json) {
    out << result.to_json() << "\n";
    return kExitOk;
  }
  const auto row = [&](const char* name, const localization::ErrorStatistics& stats) {
    out << std::left << std::setw(18) << name << std::right << std::fixed << std::setprecision(3) << std::setw(8)
        << stats.position_rmse_m << std::setw(8) << stats.position_max_m << std::setprecision(2) << std::setw(9)
        << stats.heading_rmse_rad / kDegree << std::setw(9) << stats.heading_max_rad / kDegree << std::setw(8)
        << stats.count << "\n";
  };
  out << "matched " << result.matched << " of " << result.estimates << " estimates\n";
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
        << result.options.converged_heading_rad / kDegree << " deg)\n";
  }
  (void)err;
  return kExitOk;
}

}  // namespace playerkit::amcl_offline
