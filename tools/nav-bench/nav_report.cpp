#include "nav_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <nlohmann/json.hpp>

namespace playerkit::nav_bench {

double percentile(const std::vector<double>& sorted_values, double q) {
  if (sorted_values.empty()) return 0.0;
  const double rank = std::ceil(q * static_cast<double>(sorted_values.size()));
  const auto index = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(sorted_values.size()))) - 1;
  return sorted_values[index];
}

RunTotals summarize(const std::vector<GoalOutcome>& goals, std::vector<double>& clearances,
                    std::vector<double>& vfh_ms) {
  RunTotals totals;
  totals.goals = static_cast<int>(goals.size());
  int successes = 0;
  double ratio_sum = 0.0, time_sum = 0.0, error_sum = 0.0, metres = 0.0;
  int flips = 0;
  totals.min_clearance_m = goals.empty() ? 0.0 : goals.front().min_clearance_m;
  for (const GoalOutcome& goal : goals) {
    if (goal.success) {
      ++successes;
      ratio_sum += goal.path_ratio();
      time_sum += goal.time_s;
    }
    totals.collisions += goal.collisions;
    totals.min_clearance_m = std::min(totals.min_clearance_m, goal.min_clearance_m);
    totals.stuck_events += goal.stuck_events;
    totals.replan_ms_max = std::max(totals.replan_ms_max, goal.replan_ms_max);
    error_sum += goal.localization_error_m;
    flips += goal.heading_flips;
    metres += goal.path_m;
    if (goal.relocalized) ++totals.relocalized;
  }
  if (!goals.empty()) {
    totals.success_pct = 100.0 * successes / static_cast<double>(goals.size());
    totals.loc_err_mean_m = error_sum / static_cast<double>(goals.size());
  }
  if (successes > 0) {
    totals.path_ratio_mean = ratio_sum / successes;
    totals.time_mean_s = time_sum / successes;
  }
  totals.flips_per_m = metres > 0.0 ? flips / metres : 0.0;
  std::sort(clearances.begin(), clearances.end());
  totals.clearance_p1_m = percentile(clearances, 0.01);
  std::sort(vfh_ms.begin(), vfh_ms.end());
  totals.vfh_ms_p99 = percentile(vfh_ms, 0.99);
  return totals;
}

namespace {

// To `decimals` places, as the nearest double to the decimal (0.204, not
// 0.20400000000000001, in the JSON).
double rounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

nlohmann::json goal_json(const GoalOutcome& goal) {
  return {
      {"start", {rounded(goal.start.x, 3), rounded(goal.start.y, 3)}},
      {"goal", {rounded(goal.goal.x, 3), rounded(goal.goal.y, 3),
                rounded(goal.goal.yaw * 180.0 / std::numbers::pi, 1)}},
      {"success", goal.success},
      {"ending", goal.ending},
      {"time_s", rounded(goal.time_s, 1)},
      {"time_limit_s", rounded(goal.time_limit_s, 1)},
      {"collisions", goal.collisions},
      {"min_clearance_m", rounded(goal.min_clearance_m, 3)},
      {"path_m", rounded(goal.path_m, 3)},
      {"plan_m", rounded(goal.plan_m, 3)},
      {"path_ratio", rounded(goal.path_ratio(), 3)},
      {"stuck_events", goal.stuck_events},
      {"flips_per_m", rounded(goal.flips_per_m(), 3)},
      {"replans", goal.replans},
      {"replan_ms_max", rounded(goal.replan_ms_max, 3)},
      {"loc_err_m", rounded(goal.localization_error_m, 3)},
      {"goal_distance_m", rounded(goal.goal_distance_m, 3)},
      {"goal_angle_deg", rounded(goal.goal_angle_deg, 1)},
      {"relocalized", goal.relocalized},
  };
}

}  // namespace

nlohmann::json to_json(const std::vector<GoalOutcome>& goals, const RunTotals& totals) {
  const nlohmann::json summary = {
      {"goals", totals.goals},
      {"success_pct", rounded(totals.success_pct, 1)},
      {"collisions", totals.collisions},
      {"min_clearance_m", rounded(totals.min_clearance_m, 3)},
      {"clearance_p1_m", rounded(totals.clearance_p1_m, 3)},
      {"path_ratio_mean", rounded(totals.path_ratio_mean, 3)},
      {"time_mean_s", rounded(totals.time_mean_s, 1)},
      {"stuck_events", totals.stuck_events},
      {"flips_per_m", rounded(totals.flips_per_m, 3)},
      {"replan_ms_max", rounded(totals.replan_ms_max, 3)},
      {"vfh_ms_p99", rounded(totals.vfh_ms_p99, 4)},
      {"loc_err_mean_m", rounded(totals.loc_err_mean_m, 3)},
      {"relocalized", totals.relocalized},
  };
  nlohmann::json per_goal = nlohmann::json::array();
  for (const GoalOutcome& goal : goals) per_goal.push_back(goal_json(goal));
  return {{"totals", summary}, {"goals", per_goal}};
}

std::string to_text(const std::vector<GoalOutcome>& goals, const RunTotals& totals) {
  std::string text;
  char line[256];
  std::snprintf(line, sizeof line, "%4s %16s %16s %-20s %7s %6s %6s %6s %6s %6s %5s %6s\n", "goal", "from", "to",
                "ending", "time_s", "off_m", "off_deg", "ratio", "clear", "locerr", "flips", "replan");
  text += line;
  int index = 0;
  for (const GoalOutcome& goal : goals) {
    char from[32], to[32];
    std::snprintf(from, sizeof from, "(%.2f,%.2f)", goal.start.x, goal.start.y);
    std::snprintf(to, sizeof to, "(%.2f,%.2f)", goal.goal.x, goal.goal.y);
    std::snprintf(line, sizeof line, "%4d %16s %16s %-20s %7.1f %6.2f %6.1f %6.2f %6.3f %6.3f %5d %6d\n", ++index,
                  from, to, goal.ending.c_str(), goal.time_s, goal.goal_distance_m, goal.goal_angle_deg,
                  goal.path_ratio(), goal.min_clearance_m,
                  goal.localization_error_m, goal.heading_flips, goal.replans);
    text += line;
  }
  std::snprintf(line, sizeof line,
                "goals %d  success %.1f%%  collisions %d  clearance min %.3f m p1 %.3f m  path ratio %.3f  "
                "time %.1f s\nstuck %d  flips/m %.3f  replan max %.2f ms  vfh p99 %.4f ms  loc err %.3f m  "
                "relocalized %d\n",
                totals.goals, totals.success_pct, totals.collisions, totals.min_clearance_m, totals.clearance_p1_m,
                totals.path_ratio_mean, totals.time_mean_s, totals.stuck_events, totals.flips_per_m,
                totals.replan_ms_max, totals.vfh_ms_p99, totals.loc_err_mean_m, totals.relocalized);
  text += line;
  return text;
}

}  // namespace playerkit::nav_bench
