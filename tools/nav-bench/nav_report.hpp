#pragma once
// A navigation run's figures: what happened on the way to each goal, the
// totals over the run, and both as text or JSON (the keys).

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "algorithms/geometry/pose2.hpp"

namespace playerkit::nav_bench {

struct GoalOutcome {
  geometry::Pose2 start;  // true pose when the goal was sent
  geometry::Pose2 goal;
  bool success = false;  // wavefront said reached, and truth within 0.30 m and 15 degrees, in time
  std::string ending;    // "reached", "reached off the goal", "refused", "given up", "timed out"
  double time_s = 0.0;           // simulated, from the goal to its ending
  double time_limit_s = 0.0;     // 3 x the plan at 0.3 m/s + 20 s
  int collisions = 0;            // times the robot came to touch a wall (stall began)
  double min_clearance_m = 0.0;  // nearest the robot's body came to a wall
  double path_m = 0.0;           // driven, true
  double plan_m = 0.0;           // the offline plan from the start
  int stuck_events = 0;          // vfh gave a waypoint up
  int heading_flips = 0;         // turn direction reversed (both above 0.1 rad/s)
  int replans = 0;
  double replan_ms_max = 0.0;    // longest cycle that planned, processor time
  double localization_error_m = 0.0;  // at the ending
  double goal_distance_m = 0.0;       // truth from the goal, at the ending
  double goal_angle_deg = 0.0;        // truth's heading from the goal's, at the ending
  bool relocalized = false;      // lost (> 0.5 m off): the filter was reset on the truth afterwards

  [[nodiscard]] double path_ratio() const { return plan_m > 0.0 ? path_m / plan_m : 0.0; }
  [[nodiscard]] double flips_per_m() const { return path_m > 0.0 ? heading_flips / path_m : 0.0; }
};

struct RunTotals {
  int goals = 0;
  double success_pct = 0.0;
  int collisions = 0;
  double min_clearance_m = 0.0;  // over the whole run
  double clearance_p1_m = 0.0;   // 1st percentile of the clearance over every step
  double path_ratio_mean = 0.0;  // over the goals reached
  double time_mean_s = 0.0;      // over the goals reached
  int stuck_events = 0;
  double flips_per_m = 0.0;      // all flips over all metres
  double replan_ms_max = 0.0;
  double vfh_ms_p99 = 0.0;       // processor time of one vfh cycle
  double loc_err_mean_m = 0.0;   // at the goals' endings
  int relocalized = 0;
};

// `clearances`: the body's clearance at every step; `vfh_ms`: every vfh
// cycle's time. Both are sorted in place for their percentiles.
RunTotals summarize(const std::vector<GoalOutcome>& goals, std::vector<double>& clearances,
                    std::vector<double>& vfh_ms);

// {"totals": {goals, success_pct, ...}, "goals": [{...}, ...]}
nlohmann::json to_json(const std::vector<GoalOutcome>& goals, const RunTotals& totals);
// One line per goal, then the totals; for people.
std::string to_text(const std::vector<GoalOutcome>& goals, const RunTotals& totals);

// The value at fraction `q` (0..1) of sorted `values`, nearest rank; 0 when empty.
double percentile(const std::vector<double>& sorted_values, double q);

}  // namespace playerkit::nav_bench
