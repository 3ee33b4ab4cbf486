#include "localization/trajectory_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

namespace playerkit::localization {
namespace {

std::optional<geometry::Pose2> truth_at(const Trajectory& truth, double time, const EvaluationOptions& options) {
  const auto after = std::lower_bound(truth.begin(), truth.end(), time,
                                      [](const TimedPose& pose, double t) { return pose.time < t; });
  // The nearest truth pose within the tolerance, on either side.
  const TimedPose* nearest = nullptr;
  if (after != truth.end()) nearest = &*after;
  if (after != truth.begin()) {
    const auto& before = *std::prev(after);
    if (!nearest || time - before.time < nearest->time - time) nearest = &before;
  }
  if (nearest && std::abs(nearest->time - time) <= options.time_tolerance_s) return nearest->pose;
  if (after == truth.end() || after == truth.begin()) return std::nullopt;
  const auto& before = *std::prev(after);
  if (after->time - before.time > options.max_time_gap_s) return std::nullopt;
  const double f = (time - before.time) / (after->time - before.time);
  return geometry::Pose2{before.pose.x + f * (after->pose.x - before.pose.x),
                         before.pose.y + f * (after->pose.y - before.pose.y),
                         geometry::normalize_angle(before.pose.yaw +
                                                   f * geometry::angle_difference(after->pose.yaw, before.pose.yaw))};
}

struct MatchedRow {
  double time = 0;
  double position_error = 0;
  double heading_error = 0;
  double truth_path = 0;  // truth path travelled since the first matched row
  bool within = false;
};

ErrorStatistics statistics(const std::vector<MatchedRow>& rows, std::size_t first) {
  ErrorStatistics result;
  double position_squares = 0, heading_squares = 0;
  for (std::size_t i = first; i < rows.size(); ++i) {
    ++result.count;
    position_squares += rows[i].position_error * rows[i].position_error;
    heading_squares += rows[i].heading_error * rows[i].heading_error;
    result.position_max_m = std::max(result.position_max_m, rows[i].position_error);
    result.heading_max_rad = std::max(result.heading_max_rad, rows[i].heading_error);
  }
  if (result.count > 0) {
    result.position_rmse_m = std::sqrt(position_squares / static_cast<double>(result.count));
    result.heading_rmse_rad = std::sqrt(heading_squares / static_cast<double>(result.count));
  }
  return result;
}

// The first row from which the error stays within bounds for hold_s (or to the end).
std::optional<std::size_t> convergence_row(const std::vector<MatchedRow>& rows, double hold_s) {
  std::size_t i = 0;
  while (i < rows.size()) {
    if (!rows[i].within) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < rows.size() && rows[j + 1].within && rows[j + 1].time - rows[i].time < hold_s) ++j;
    const bool held = j + 1 == rows.size() || rows[j + 1].within;
    if (held) return i;
    i = j + 1;
  }
  return std::nullopt;
}

// How many claimed standard deviations an error is: the position's
// Mahalanobis distance, and the heading's ratio. A spread of zero makes any
// error infinitely many (a filter that claims certainty and is off).
struct ErrorInSigmas {
  double position = 0;
  double heading = 0;
};

ErrorInSigmas error_in_sigmas(const geometry::Pose2& estimate, const geometry::Pose2& truth, const PoseSpread& spread) {
  const double dx = estimate.x - truth.x, dy = estimate.y - truth.y;
  const double determinant = spread.var_x * spread.var_y - spread.cov_xy * spread.cov_xy;
  ErrorInSigmas result;
  if (determinant > 0.0 && spread.var_x > 0.0) {
    const double squared = (spread.var_y * dx * dx - 2.0 * spread.cov_xy * dx * dy + spread.var_x * dy * dy) / determinant;
    result.position = std::sqrt(std::max(0.0, squared));
  } else {
    result.position = dx == 0.0 && dy == 0.0 ? 0.0 : HUGE_VAL;
  }
  const double heading_error = std::abs(geometry::angle_difference(estimate.yaw, truth.yaw));
  result.heading = spread.var_yaw > 0.0 ? heading_error / std::sqrt(spread.var_yaw) : (heading_error == 0.0 ? 0.0 : HUGE_VAL);
  return result;
}

nlohmann::json statistics_json(const ErrorStatistics& s) {
  return {{"count", s.count},
          {"position_rmse_m", s.position_rmse_m},
          {"position_max_m", s.position_max_m},
          {"heading_rmse_rad", s.heading_rmse_rad},
          {"heading_max_rad", s.heading_max_rad}};
}

// null when the estimate claimed no spread; infinite sigmas (a zero spread
// and an error) as null too, JSON having no infinity.
nlohmann::json coverage_json(const CoverageStatistics& c) {
  if (c.rows == 0) return nullptr;
  const auto finite_or_null = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"rows", c.rows},
          {"inside_2sigma", c.inside_2sigma},
          {"share", c.share()},
          {"confidently_wrong", c.confidently_wrong},
          {"worst_position_sigmas", finite_or_null(c.worst_position_sigmas)},
          {"worst_heading_sigmas", finite_or_null(c.worst_heading_sigmas)}};
}

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

}  // namespace

TrajectoryEvaluation evaluate_trajectory(const Trajectory& estimate, const Trajectory& truth_in,
                                         const EvaluationOptions& options) {
  Trajectory truth = truth_in;
  std::stable_sort(truth.begin(), truth.end(), [](const TimedPose& a, const TimedPose& b) { return a.time < b.time; });

  TrajectoryEvaluation result;
  result.options = options;
  result.estimates = estimate.size();
  std::vector<MatchedRow> rows;
  std::optional<geometry::Pose2> previous_truth;
  double path = 0;
  for (const auto& entry : estimate) {
    const auto true_pose = truth_at(truth, entry.time, options);
    if (!true_pose) continue;
    if (previous_truth) path += std::hypot(true_pose->x - previous_truth->x, true_pose->y - previous_truth->y);
    previous_truth = true_pose;
    MatchedRow row;
    row.time = entry.time;
    row.position_error = std::hypot(entry.pose.x - true_pose->x, entry.pose.y - true_pose->y);
    row.heading_error = std::abs(geometry::angle_difference(entry.pose.yaw, true_pose->yaw));
    row.truth_path = path;
    row.within = row.position_error <= options.converged_position_m &&
                 row.heading_error <= options.converged_heading_rad;
    rows.push_back(row);
    if (entry.spread) {
      const ErrorInSigmas sigmas = error_in_sigmas(entry.pose, *true_pose, *entry.spread);
      CoverageStatistics& coverage = result.coverage;
      ++coverage.rows;
      const bool inside = sigmas.position <= 2.0 && sigmas.heading <= 2.0;
      if (inside) ++coverage.inside_2sigma;
      if (!inside && (row.position_error > options.confident_position_m ||
                      row.heading_error > options.confident_heading_rad)) {
        ++coverage.confidently_wrong;
      }
      coverage.worst_position_sigmas = std::max(coverage.worst_position_sigmas, sigmas.position);
      coverage.worst_heading_sigmas = std::max(coverage.worst_heading_sigmas, sigmas.heading);
    }
  }
  result.matched = rows.size();
  result.all = statistics(rows, 0);
  if (const auto converged = convergence_row(rows, options.convergence_hold_s)) {
    result.convergence_time_s = rows[*converged].time - estimate.front().time;
    result.convergence_distance_m = rows[*converged].truth_path;
    result.after_convergence = statistics(rows, *converged);
    bool in_episode = false;
    double episode_start = 0;
    for (std::size_t i = *converged; i < rows.size(); ++i) {
      if (rows[i].within) {
        if (in_episode) result.longest_lost_s = std::max(result.longest_lost_s, rows[i].time - episode_start);
        in_episode = false;
        continue;
      }
      ++result.rows_outside_after_convergence;
      if (!in_episode) {
        ++result.lost_episodes;
        in_episode = true;
        episode_start = rows[i].time;
      }
    }
    if (in_episode) result.longest_lost_s = std::max(result.longest_lost_s, rows.back().time - episode_start);
  }
  return result;
}

std::string TrajectoryEvaluation::to_json(int indent) const {
  const nlohmann::json json{
      {"estimates", estimates},
      {"matched", matched},
      {"matched_by", matched_by_scan_order ? "scan_order" : "time"},
      {"all", statistics_json(all)},
      {"converged", converged()},
      {"convergence_time_s", optional_json(convergence_time_s)},
      {"convergence_distance_m", optional_json(convergence_distance_m)},
      {"after_convergence", statistics_json(after_convergence)},
      {"lost_episodes", lost_episodes},
      {"rows_outside_after_convergence", rows_outside_after_convergence},
      {"longest_lost_s", longest_lost_s},
      {"coverage", coverage_json(coverage)},
      {"options",
       {{"time_tolerance_s", options.time_tolerance_s},
        {"max_time_gap_s", options.max_time_gap_s},
        {"converged_position_m", options.converged_position_m},
        {"converged_heading_rad", options.converged_heading_rad},
        {"convergence_hold_s", options.convergence_hold_s},
        {"confident_position_m", options.confident_position_m},
        {"confident_heading_rad", options.confident_heading_rad}}}};
  return json.dump(indent);
}

}  // namespace playerkit::localization
