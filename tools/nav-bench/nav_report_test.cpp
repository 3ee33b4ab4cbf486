#include "nav_report.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace playerkit::nav_bench {
namespace nav_report_test {

GoalOutcome outcome(bool success, double path, double plan, int flips, double clearance, double error) {
  GoalOutcome goal;
  goal.success = success;
  goal.ending = success ? "reached" : "timed out";
  goal.path_m = path;
  goal.plan_m = plan;
  goal.heading_flips = flips;
  goal.min_clearance_m = clearance;
  goal.localization_error_m = error;
  goal.time_s = path / 0.25;
  return goal;
}

TEST(NavReport, TotalsAverageTheReachedGoalsAndCountEverything) {
  const std::vector<GoalOutcome> goals{outcome(true, 11.0, 10.0, 1, 0.20, 0.05),
                                       outcome(true, 6.0, 5.0, 0, 0.10, 0.07),
                                       outcome(false, 3.0, 8.0, 2, 0.30, 0.60)};
  std::vector<double> clearances{0.5, 0.1, 0.3, 0.2};
  std::vector<double> vfh(100);
  for (int i = 0; i < 100; ++i) vfh[static_cast<std::size_t>(i)] = 100.0 - i;  // 1..100 ms, unsorted
  const RunTotals totals = summarize(goals, clearances, vfh);
  EXPECT_EQ(totals.goals, 3);
  EXPECT_NEAR(totals.success_pct, 200.0 / 3.0, 1e-9);
  EXPECT_NEAR(totals.path_ratio_mean, (1.1 + 1.2) / 2, 1e-9) << "only the goals reached";
  EXPECT_NEAR(totals.time_mean_s, (44.0 + 24.0) / 2, 1e-9);
  EXPECT_NEAR(totals.flips_per_m, 3.0 / 20.0, 1e-9) << "all flips over all metres";
  EXPECT_NEAR(totals.min_clearance_m, 0.10, 1e-12);
  EXPECT_NEAR(totals.clearance_p1_m, 0.1, 1e-12);
  EXPECT_NEAR(totals.vfh_ms_p99, 99.0, 1e-12);
  EXPECT_NEAR(totals.loc_err_mean_m, 0.24, 1e-12);
}

TEST(NavReport, JsonHasTheIssuesKeysInTotalsAndOneObjectPerGoal) {
  const std::vector<GoalOutcome> goals{outcome(true, 11.0, 10.0, 1, 0.2, 0.05)};
  std::vector<double> clearances{0.2}, vfh{0.01};
  const nlohmann::json report = to_json(goals, summarize(goals, clearances, vfh));
  for (const char* key : {"goals", "success_pct", "collisions", "min_clearance_m", "path_ratio_mean", "time_mean_s",
                          "stuck_events", "flips_per_m", "replan_ms_max", "vfh_ms_p99", "loc_err_mean_m"}) {
    EXPECT_TRUE(report["totals"].contains(key)) << key;
  }
  ASSERT_EQ(report["goals"].size(), 1u);
  EXPECT_EQ(report["goals"][0]["ending"], "reached");
  EXPECT_DOUBLE_EQ(report["goals"][0]["path_ratio"].get<double>(), 1.1);
  EXPECT_EQ(report["totals"]["success_pct"].get<double>(), 100.0);
}

TEST(NavReport, PercentileIsTheNearestRank) {
  EXPECT_EQ(percentile({}, 0.5), 0.0);
  EXPECT_EQ(percentile({1.0, 2.0, 3.0, 4.0}, 0.5), 2.0);
  EXPECT_EQ(percentile({1.0, 2.0, 3.0, 4.0}, 0.0), 1.0);
  EXPECT_EQ(percentile({1.0, 2.0, 3.0, 4.0}, 1.0), 4.0);
}

}  // namespace nav_report_test
}  // namespace playerkit::nav_bench
