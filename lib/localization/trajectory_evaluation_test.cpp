// Trajectory CSV reading and absolute trajectory error on synthetic
// trajectories with known answers.

#include "localization/trajectory_evaluation.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "localization/localization_test_support.hpp"

namespace playerkit::localization {
namespace trajectory_evaluation_test {

constexpr double kDegree = std::numbers::pi / 180;

// 1 m/s along x for `seconds`, one pose per 0.5 s.
Trajectory straight_truth(double seconds) {
  Trajectory truth;
  for (double t = 0; t <= seconds + 1e-9; t += 0.5) truth.push_back({t, {t, 0, 0}});
  return truth;
}

TEST(TrajectoryEvaluation, IdenticalTrajectoriesHaveNoError) {
  const auto truth = straight_truth(10);
  const auto result = evaluate_trajectory(truth, truth);
  EXPECT_EQ(result.estimates, truth.size());
  EXPECT_EQ(result.matched, truth.size());
  EXPECT_EQ(result.all.position_rmse_m, 0.0);
  EXPECT_EQ(result.all.heading_max_rad, 0.0);
  ASSERT_TRUE(result.converged());
  EXPECT_EQ(*result.convergence_time_s, 0.0);
  EXPECT_EQ(*result.convergence_distance_m, 0.0);
  EXPECT_EQ(result.lost_episodes, 0u);
}

TEST(TrajectoryEvaluation, ConstantOffsetIsTheRmse) {
  const auto truth = straight_truth(10);
  Trajectory estimate = truth;
  for (auto& entry : estimate) entry.pose.y += 0.1;
  const auto result = evaluate_trajectory(estimate, truth);
  EXPECT_NEAR(result.all.position_rmse_m, 0.1, 1e-12);
  EXPECT_NEAR(result.all.position_max_m, 0.1, 1e-12);
  EXPECT_EQ(result.all.count, truth.size());
}

TEST(TrajectoryEvaluation, HeadingErrorsWrapAroundTheCircle) {
  const Trajectory truth{{0, {0, 0, -179 * kDegree}}, {1, {0, 0, -179 * kDegree}}};
  const Trajectory estimate{{0, {0, 0, 179 * kDegree}}, {1, {0, 0, 179 * kDegree}}};
  const auto result = evaluate_trajectory(estimate, truth);
  EXPECT_NEAR(result.all.heading_rmse_rad, 2 * kDegree, 1e-12);
  EXPECT_NEAR(result.all.heading_max_rad, 2 * kDegree, 1e-12);
}

TEST(TrajectoryEvaluation, EstimatesBetweenTruthPosesAreInterpolatedOnTheCircle) {
  const Trajectory truth{{0, {0, 0, 170 * kDegree}}, {1, {2, 4, -170 * kDegree}}, {10, {9, 9, 0}}};
  // Halfway: (1, 2), heading 180 deg (through the short arc, not through 0).
  const Trajectory estimate{{0.5, {1, 2, 180 * kDegree}}, {5, {0, 0, 0}}, {20, {0, 0, 0}}};
  const auto result = evaluate_trajectory(estimate, truth);
  EXPECT_EQ(result.estimates, 3u);
  EXPECT_EQ(result.matched, 1u);  // t = 5 falls in a 9 s gap, t = 20 after the truth
  EXPECT_NEAR(result.all.position_max_m, 0.0, 1e-12);
  EXPECT_NEAR(result.all.heading_max_rad, 0.0, 1e-12);
}

TEST(TrajectoryEvaluation, ConvergenceTimeAndDistanceOfAConvergingEstimate) {
  const auto truth = straight_truth(30);
  Trajectory estimate;
  // 2 m off, shrinking 0.2 m per second: within 0.3 m from t = 8.5 s on; a
  // brief excursion at 20 s counts as one lost episode.
  for (const auto& entry : truth) {
    const double offset = std::max(0.0, 2.0 - 0.2 * entry.time);
    const bool excursion = std::abs(entry.time - 20.0) < 0.25;
    estimate.push_back({entry.time, {entry.pose.x, entry.pose.y + (excursion ? 1.0 : offset), 0}});
  }
  const auto result = evaluate_trajectory(estimate, truth);
  ASSERT_TRUE(result.converged());
  EXPECT_DOUBLE_EQ(*result.convergence_time_s, 8.5);
  EXPECT_NEAR(*result.convergence_distance_m, 8.5, 1e-9);
  EXPECT_EQ(result.lost_episodes, 1u);
  EXPECT_EQ(result.rows_outside_after_convergence, 1u);
  EXPECT_DOUBLE_EQ(result.longest_lost_s, 0.5);  // out at 20 s, back at 20.5 s
  EXPECT_NEAR(result.after_convergence.position_max_m, 1.0, 1e-12);
  EXPECT_EQ(result.after_convergence.count, truth.size() - 17);
  EXPECT_NE(result.to_json().find("\"convergence_time_s\": 8.5"), std::string::npos) << result.to_json();
}

TEST(TrajectoryEvaluation, AnEpisodeThatNeverEndsLastsToTheLastRow) {
  const auto truth = straight_truth(30);
  Trajectory estimate = truth;
  for (auto& entry : estimate) {
    if (std::abs(entry.time - 10.0) < 0.75) entry.pose.yaw = 15 * kDegree;  // 9.5 .. 10.5 s: heading off
    if (entry.time >= 22.0) entry.pose.y = 0.5;                             // from 22 s to the end: position off
  }
  const auto result = evaluate_trajectory(estimate, truth);
  ASSERT_TRUE(result.converged());
  EXPECT_EQ(result.lost_episodes, 2u);
  EXPECT_EQ(result.rows_outside_after_convergence, 3u + 17u);
  EXPECT_DOUBLE_EQ(result.longest_lost_s, 8.0);
  EXPECT_NE(result.to_json().find("\"longest_lost_s\": 8.0"), std::string::npos) << result.to_json();
}

TEST(TrajectoryEvaluation, ABriefVisitWithinBoundsIsNotConvergence) {
  const auto truth = straight_truth(20);
  Trajectory estimate = truth;
  for (auto& entry : estimate) {
    if (entry.time != 2.0 && entry.time < 12.0) entry.pose.x += 1.0;  // right only at t = 2, then from 12 on
  }
  const auto result = evaluate_trajectory(estimate, truth);
  ASSERT_TRUE(result.converged());
  EXPECT_DOUBLE_EQ(*result.convergence_time_s, 12.0);

  for (auto& entry : estimate) entry.pose.x += 5;
  const auto never = evaluate_trajectory(estimate, truth);
  EXPECT_FALSE(never.converged());
  EXPECT_NE(never.to_json().find("\"convergence_time_s\": null"), std::string::npos);
}

Trajectory read_csv(const std::string& text) {
  std::istringstream in(text);
  return read_trajectory_csv(in, "estimate.csv");
}

std::string csv_error(const std::string& text) {
  try {
    read_csv(text);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "no error";
}

TEST(TrajectoryCsv, ReadsNamedColumnsInAnyOrder) {
  const auto trajectory = read_csv("# from amcl-offline\nyaw, time,x,weight,y\n0.5,10.25,1,0.3,-2\n\n-3.1,11,+2.5,1,0\n");
  ASSERT_EQ(trajectory.size(), 2u);
  EXPECT_EQ(trajectory[0].time, 10.25);
  EXPECT_EQ(trajectory[0].pose, (geometry::Pose2{1, -2, 0.5}));
  EXPECT_EQ(trajectory[1].pose, (geometry::Pose2{2.5, 0, -3.1}));
}

TEST(TrajectoryCsv, ErrorsNameTheLine) {
  EXPECT_EQ(csv_error("time,x,y\n1,2,3\n"), "estimate.csv:1: the header has no column 'yaw' (it needs time, x, y, yaw)");
  EXPECT_EQ(csv_error("time,x,y,yaw\n1,2,3,4\n1,2,3\n"), "estimate.csv:3: 3 fields, the header needs 4");
  EXPECT_EQ(csv_error("time,x,y,yaw\n1,2,abc,4\n"), "estimate.csv:2: column 'y': 'abc' is not a number");
  EXPECT_EQ(csv_error("time,x,y,yaw\n1,2,nan,4\n"), "estimate.csv:2: column 'y': 'nan' is not a number");
  EXPECT_EQ(csv_error(""), "estimate.csv: no header line (time,x,y,yaw)");
  EXPECT_THROW(read_trajectory_csv(std::filesystem::path("/nonexistent/estimate.csv")), std::runtime_error);
}

TEST(TrajectoryCsv, WrittenTrajectoriesReadBack) {
  const Trajectory trajectory{{1.5, {0.123456789, -2, 3.1}}, {2.0, {4, 5, -0.25}}};
  std::ostringstream out;
  write_trajectory_csv(out, trajectory);
  const auto back = read_csv(out.str());
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[0].pose, trajectory[0].pose);
  EXPECT_EQ(back[1].time, 2.0);
}

// Each row's error against the spread it claims; the truth stands still at
// the origin, heading 0.
TEST(TrajectoryEvaluation, CoverageCountsTheTruthInsideTheClaimed2SigmaAndTheConfidentlyWrong) {
  Trajectory truth;
  for (int t = 0; t <= 7; ++t) truth.push_back({double(t), {0, 0, 0}});
  const PoseSpread tight{0.01, 0.01, 0.0, 0.01};  // 0.1 m, 0.1 rad
  const PoseSpread along_the_diagonal{0.5, 0.5, 0.49, 0.01};  // 0.995 m along (1,1), 0.1 m across
  const Trajectory estimate{
      {0, {0.1, 0, 0}, tight},                           // 1 sigma: inside
      {1, {0.3, 0, 0}, tight},                           // 3 sigma, 0.3 m: outside, not far
      {2, {0.6, 0, 0}, tight},                           // 6 sigma, 0.6 m: confidently wrong
      {3, {0.6, 0, 0}, PoseSpread{0.25, 0.25, 0, 0.01}},  // 1.2 sigma: inside
      {4, {0.5, 0.5, 0}, along_the_diagonal},            // 0.71 m along the long axis: inside
      {5, {0.2, -0.2, 0}, along_the_diagonal},           // 0.28 m across: 2.8 sigma, outside
      {6, {0, 0, 30 * kDegree}, PoseSpread{0.01, 0.01, 0, std::pow(20 * kDegree, 2)}},  // 1.5 sigma: inside
      {7, {0, 0, 30 * kDegree}, tight}};                 // 5.2 sigma and past 20 degrees: confidently wrong
  const auto coverage = evaluate_trajectory(estimate, truth).coverage;
  EXPECT_EQ(coverage.rows, 8u);
  EXPECT_EQ(coverage.inside_2sigma, 4u);
  EXPECT_EQ(coverage.confidently_wrong, 2u);
  EXPECT_DOUBLE_EQ(coverage.share(), 0.5);
  EXPECT_NEAR(coverage.worst_position_sigmas, 6.0, 1e-9);
  EXPECT_NEAR(coverage.worst_heading_sigmas, (30 * kDegree) / 0.1, 1e-9);
}

TEST(TrajectoryEvaluation, NoClaimedSpreadNoCoverage) {
  const auto truth = straight_truth(3);
  const auto result = evaluate_trajectory(truth, truth);
  EXPECT_EQ(result.coverage.rows, 0u);
  EXPECT_NE(result.to_json().find("\"coverage\": null"), std::string::npos);
}

TEST(TrajectoryCsv, LocalizesStandardDeviationsAndCovarianceAreTheClaimedSpread) {
  const auto rows = read_csv(
      "time,x,y,yaw,std_x,std_y,std_yaw,particles,cov_xy\n"
      "1,2,3,0.5,0.2,0.3,0.1,100,-0.01\n");
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_TRUE(rows[0].spread);
  EXPECT_NEAR(rows[0].spread->var_x, 0.04, 1e-12);
  EXPECT_NEAR(rows[0].spread->var_y, 0.09, 1e-12);
  EXPECT_NEAR(rows[0].spread->var_yaw, 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(rows[0].spread->cov_xy, -0.01);
  // An estimate from before cov_xy: uncorrelated; one without std columns: none.
  EXPECT_EQ(read_csv("time,x,y,yaw,std_x,std_y,std_yaw\n1,2,3,0.5,0.2,0.3,0.1\n")[0].spread->cov_xy, 0.0);
  EXPECT_FALSE(read_csv("time,x,y,yaw\n1,2,3,0.5\n")[0].spread);
  EXPECT_THROW(read_csv("time,x,y,yaw,std_x,std_y,std_yaw\n1,2,3,0.5,0.2,x,0.1\n"), std::runtime_error);
}

TEST(TruthFromLog, IntelTruthIsTheScanPoses) {
  const auto truth = truth_from_log(testing::radish("intel-corrected.log.gz"));
  ASSERT_EQ(truth.size(), 910u);
  EXPECT_DOUBLE_EQ(truth.front().time, 32.9068);
  EXPECT_DOUBLE_EQ(truth.front().pose.x, 0.600266);
  // Evaluated against itself: no error, converged at once.
  const auto result = evaluate_trajectory(truth, truth);
  EXPECT_EQ(result.matched, 910u);
  EXPECT_EQ(result.all.position_max_m, 0.0);
}

}  // namespace trajectory_evaluation_test
}  // namespace playerkit::localization
