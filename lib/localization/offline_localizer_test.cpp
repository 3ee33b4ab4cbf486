#include "localization/offline_localizer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "localization/estimate_writer.hpp"
#include "localization/localization_test_support.hpp"
#include "localization/map_from_log.hpp"
#include "localization/odometry_perturbation.hpp"
#include "localization/trajectory_evaluation.hpp"

namespace playerkit::localization {
namespace offline_localizer_test {

// The Intel log, its map from its own corrected poses (coarse, to keep the
// test quick) and its odometry degraded by the default model.
struct IntelFixture : ::testing::Test {
  static void SetUpTestSuite() {
    grid::OccupancyMappingParameters mapping;
    mapping.resolution = 0.1;
    map = std::make_shared<const grid::OccupancyGrid>(
        map_from_log(testing::radish("intel-corrected.log.gz"), mapping).grid);
    // Shared by the suite's tests, so not in a per-test directory.
    odometry_path = std::filesystem::temp_directory_path() /
                    ("offline_localizer_test_" + std::to_string(::getpid()) + ".log");
    std::ofstream out(odometry_path);
    perturb_log(testing::radish("intel-corrected.log.gz"), out, OdometryErrorModel{}, 1);
  }
  static void TearDownTestSuite() {
    std::filesystem::remove(odometry_path);
    map.reset();
  }
  static std::filesystem::path odometry_log() { return odometry_path; }

  static std::vector<LocalizedScan> run(const OfflineLocalizationOptions& options, LocalizationSummary* summary = nullptr) {
    std::vector<LocalizedScan> rows;
    const auto result = localize_log(odometry_log(), map, options,
                                     [&](const LocalizedScan& row, const LoggedScan&) { rows.push_back(row); });
    if (summary != nullptr) *summary = result;
    return rows;
  }

  static inline std::shared_ptr<const grid::OccupancyGrid> map;
  static inline std::filesystem::path odometry_path;
};

Trajectory as_trajectory(const std::vector<LocalizedScan>& rows) {
  Trajectory trajectory;
  for (const auto& row : rows) trajectory.push_back({row.time, row.estimate.mean});
  return trajectory;
}

TEST_F(IntelFixture, TracksTheRobotFromItsTrueStartThroughDegradedOdometry) {
  OfflineLocalizationOptions options;
  options.initial.kind = InitialBelief::Kind::first_truth;
  LocalizationSummary summary;
  const auto rows = run(options, &summary);
  EXPECT_EQ(summary.scans, 910u);
  EXPECT_EQ(rows.size(), 910u);
  EXPECT_GT(summary.laser_updates, 700u);
  EXPECT_NEAR(summary.log_seconds, 2650.86, 0.01);
  EXPECT_EQ(summary.global_particles, 0u);  // not a search, though the filter begins as one
  EXPECT_FALSE(summary.search_ended_at);

  const auto truth = truth_from_log(testing::radish("intel-corrected.log.gz"));
  const auto tracked = evaluate_trajectory(as_trajectory(rows), truth);
  EXPECT_EQ(tracked.matched, 910u);
  EXPECT_LT(tracked.all.position_rmse_m, 0.15);
  // The 0.1 m map costs heading accuracy (docs/amcl.md: 1.9 deg on 0.05 m).
  EXPECT_LT(tracked.all.heading_rmse_rad, 6.0 * std::numbers::pi / 180.0);

  // What the filter corrected: the odometry alone ends metres away.
  Trajectory odometry;
  LoggedScanReader reader(odometry_log());
  while (auto scan = reader.next()) odometry.push_back({scan->time, *scan->odometry});
  EXPECT_GT(evaluate_trajectory(odometry, truth).all.position_rmse_m, 5.0);
}

TEST_F(IntelFixture, TheSameSeedGivesTheSameEstimates) {
  OfflineLocalizationOptions options;
  options.initial.kind = InitialBelief::Kind::first_truth;
  options.seed = 5;
  const auto first = run(options);
  const auto second = run(options);
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    ASSERT_EQ(first[i].estimate.mean, second[i].estimate.mean) << "row " << i;
    ASSERT_EQ(first[i].particles, second[i].particles) << "row " << i;
  }
}

TEST_F(IntelFixture, AStartPoseFarFromTheTruthIsNotHiddenByTheOutput) {
  OfflineLocalizationOptions options;
  options.initial.kind = InitialBelief::Kind::pose;
  options.initial.pose = {10.0, 10.0, 0.0};  // nowhere near the start (0.6, 0)
  const auto rows = run(options);
  ASSERT_FALSE(rows.empty());
  EXPECT_GT(std::hypot(rows.front().estimate.mean.x - 0.6, rows.front().estimate.mean.y), 5.0);
}

// A recording that kept a laser scan before the truth device's first sample
// (player-log record subscribes to each device in turn).
constexpr const char* kTruthAfterTheFirstScan =
    "## Player version 1.5 \n"
    "## File version 0.0.0 \n"
    "0000000010.000 robot 6665 position 00 0000000010.000 +01.000 +02.000 +0.500 +00.000 +00.000 +00.000 0\n"
    "0000000010.050 robot 6665 laser 00 0000000010.050 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n"
    "0000000010.100 robot 6665 position 00 0000000010.100 +01.100 +02.000 +0.600 +00.000 +00.000 +00.000 0\n"
    "0000000010.150 robot 6665 laser 00 0000000010.150 -1.5708 +1.5708 +1.5708 0003 4.000  0 5.000  0 6.000  0 \n"
    "0000000010.160 robot 6665 truth 00 0000000010.150 +05.000 +06.000 +0.700\n"
    "0000000010.170 robot 6665 position 00 0000000010.150 +01.200 +02.000 +0.650 +00.000 +00.000 +00.000 0\n"
    "0000000010.250 robot 6665 laser 00 0000000010.250 -1.5708 +1.5708 +1.5708 0003 7.000  0 8.000  0 9.000  0 \n";

std::shared_ptr<const grid::OccupancyGrid> free_room() {
  return std::make_shared<const grid::OccupancyGrid>(200, 200, 0.05, Eigen::Vector2d::Zero(), grid::CellState::free);
}

TEST(LocalizeLog, StartingAtTheTruthSkipsTheScansBeforeTheFirstTruePose) {
  testing::TemporaryDirectory directory;
  OfflineLocalizationOptions options;
  options.initial.kind = InitialBelief::Kind::first_truth;
  std::vector<LocalizedScan> rows;
  const auto summary = localize_log(directory.write("robot.log", kTruthAfterTheFirstScan), free_room(), options,
                                    [&](const LocalizedScan& row, const LoggedScan&) { rows.push_back(row); });
  EXPECT_EQ(summary.scans_before_truth, 1u);
  EXPECT_EQ(summary.scans, 2u);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_DOUBLE_EQ(rows[0].time, 10.15);
  // Started at the truth (5, 6, 0.7), not at the odometry (1.2, 2, 0.65).
  EXPECT_NEAR(rows[0].estimate.mean.x, 5.0, 0.05);
  EXPECT_NEAR(rows[0].estimate.mean.y, 6.0, 0.05);
  EXPECT_NEAR(rows[0].estimate.mean.yaw, 0.7, 0.03);
}

TEST(LocalizeLog, StartingAtTheTruthOfALogWithoutTruthIsAClearError) {
  testing::TemporaryDirectory directory;
  std::string without_truth = kTruthAfterTheFirstScan;
  without_truth.erase(without_truth.find("0000000010.160"), without_truth.find("0000000010.170") -
                                                                without_truth.find("0000000010.160"));
  OfflineLocalizationOptions options;
  options.initial.kind = InitialBelief::Kind::first_truth;
  const auto log = directory.write("robot.log", without_truth);
  try {
    localize_log(log, free_room(), options, [](const LocalizedScan&, const LoggedScan&) {});
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_EQ(std::string(error.what()), log.string() + ": no scan with odometry has a true pose to start from");
  }
}

TEST(EstimateWriter, CsvHasTheDocumentedHeaderAndUnits) {
  std::ostringstream out;
  EstimateWriter writer(out, EstimateFormat::csv);
  LocalizedScan row;
  row.time = 12.5;
  row.estimate.mean = {1.25, -2.5, 0.5};
  row.estimate.covariance = Eigen::Vector3d(0.04, 0.09, 0.01).asDiagonal();
  row.estimate.covariance(0, 1) = row.estimate.covariance(1, 0) = -0.0123;
  row.particles = 321;
  writer.write(row);
  EXPECT_EQ(out.str(),
            "time,x,y,yaw,std_x,std_y,std_yaw,particles,cov_xy\n"
            "12.500000,1.2500,-2.5000,0.50000,0.2000,0.3000,0.10000,321,-0.01230000\n");
}

TEST(EstimateWriter, JsonLinesCarryTheSameKeys) {
  std::ostringstream out;
  EstimateWriter writer(out, EstimateFormat::json);
  LocalizedScan row;
  row.time = 1;
  row.particles = 7;
  writer.write(row);
  EXPECT_EQ(out.str(),
            "{\"time\":1.000000,\"x\":0.0000,\"y\":0.0000,\"yaw\":0.00000,\"std_x\":0.0000,"
            "\"std_y\":0.0000,\"std_yaw\":0.00000,\"particles\":7,\"cov_xy\":0.00000000}\n");
}

}  // namespace offline_localizer_test
}  // namespace playerkit::localization
