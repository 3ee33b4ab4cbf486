#pragma once
// How far an estimated trajectory is from the truth: absolute trajectory error
// (no alignment: the estimate is in the map frame the truth is in), and when
// the estimate converged.
//
//   auto result = localization::evaluate_trajectory(estimate, truth, {});
//   std::cout << result.to_json() << '\n';
//
// Matching: each estimate is compared with the truth at its own time: a truth
// pose within time_tolerance, else the interpolation of the truth poses just
// before and after it when they are at most max_time_gap apart (position
// linear, heading along the shorter arc); otherwise it is unmatched.
// Convergence: the first matched estimate from which position error <=
// converged_position_m and heading error <= converged_heading_rad hold for at
// least convergence_hold_s (or to the end of the estimate). "Lost" after it
// counts the times the error leaves those bounds again.
// Coverage: when the estimate claims a spread (localize's std_x, std_y,
// std_yaw, cov_xy), how often the truth lies inside the claimed 2-sigma
// ellipse (Mahalanobis distance of the position error at most 2) and the
// 2-sigma heading interval, and how often the estimate was far off (past
// confident_position_m or confident_heading_rad) outside them: confidently
// wrong.

#include <cstddef>
#include <numbers>
#include <optional>
#include <string>

#include "localization/trajectory.hpp"

namespace playerkit::localization {

struct EvaluationOptions {
  double time_tolerance_s = 1e-3;
  double max_time_gap_s = 1.0;
  double converged_position_m = 0.3;
  double converged_heading_rad = 10.0 * std::numbers::pi / 180.0;
  double convergence_hold_s = 5.0;
  double confident_position_m = 0.5;
  double confident_heading_rad = 20.0 * std::numbers::pi / 180.0;
};

struct CoverageStatistics {
  std::size_t rows = 0;            // matched rows with a claimed spread
  std::size_t inside_2sigma = 0;   // truth inside both the ellipse and the heading interval
  std::size_t confidently_wrong = 0;  // outside them and far off
  double worst_position_sigmas = 0;  // largest Mahalanobis distance of the position error
  double worst_heading_sigmas = 0;   // largest heading error in claimed standard deviations
  double share() const { return rows > 0 ? static_cast<double>(inside_2sigma) / static_cast<double>(rows) : 0.0; }
};

struct ErrorStatistics {
  std::size_t count = 0;
  double position_rmse_m = 0;
  double position_max_m = 0;
  double heading_rmse_rad = 0;
  double heading_max_rad = 0;
};

struct TrajectoryEvaluation {
  std::size_t estimates = 0;
  std::size_t matched = 0;
  ErrorStatistics all;                 // every matched estimate
  ErrorStatistics after_convergence;   // from the convergence estimate on (empty if none)
  std::optional<double> convergence_time_s;      // since the first estimate
  std::optional<double> convergence_distance_m;  // truth path from the first matched estimate
  std::size_t lost_episodes = 0;                 // times the error left the bounds after convergence
  std::size_t rows_outside_after_convergence = 0;
  // From the first row of an episode to the first row back within the
  // bounds (or the last row): tells a one-scan blip from a real loss.
  double longest_lost_s = 0;
  // Set by the caller when the estimate was paired by scan order
  // (scan_order_matching.hpp): its times are the truth's file-order clock.
  bool matched_by_scan_order = false;
  // Empty (rows 0) when the estimate claims no spread.
  CoverageStatistics coverage;
  EvaluationOptions options;

  bool converged() const { return convergence_time_s.has_value(); }
  // One JSON object (field names as above, null when not converged).
  std::string to_json(int indent = 2) const;
};

// The truth need not be sorted; the estimate is taken in its order (by time).
TrajectoryEvaluation evaluate_trajectory(const Trajectory& estimate, const Trajectory& truth,
                                         const EvaluationOptions& options = {});

}  // namespace playerkit::localization
