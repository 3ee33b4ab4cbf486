// The odometry error model on synthetic paths (analytic answers, statistics
// with fixed seeds), and perturb_log on the intel log and a small Player log.

#include "localization/odometry_perturbation.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "log/text_log_tokens.hpp"
#include "localization/localization_test_support.hpp"
#include "localization/logged_scan_reader.hpp"
#include "log/log_input.hpp"

namespace playerkit::localization {
namespace odometry_perturbation_test {

using log::split_line_tokens;
using testing::radish;
using testing::TemporaryDirectory;

// A straight drive of `length` m in `steps` steps from `start`, heading kept.
std::vector<geometry::Pose2> straight(const geometry::Pose2& start, double length, int steps) {
  std::vector<geometry::Pose2> poses;
  for (int i = 0; i <= steps; ++i) poses.push_back(start.compose({length * i / steps, 0, 0}));
  return poses;
}

std::vector<geometry::Pose2> perturbed(const std::vector<geometry::Pose2>& truth, const OdometryErrorModel& model,
                                       std::uint64_t seed) {
  OdometryPerturber perturber(model, seed);
  std::vector<geometry::Pose2> odometry;
  for (const auto& pose : truth) odometry.push_back(perturber.next(pose));
  return odometry;
}

// A wiggly path: forward, turning both ways, a reverse leg.
std::vector<geometry::Pose2> wiggly_path() {
  std::vector<geometry::Pose2> poses{{1, -2, 0.3}};
  for (int i = 0; i < 200; ++i) {
    const double forward = i % 50 < 40 ? 0.1 : -0.05;
    poses.push_back(poses.back().compose({forward, 0.0, 0.2 * std::sin(i * 0.1)}));
  }
  return poses;
}

TEST(OdometryPerturber, ZeroErrorModelGivesTheTruth) {
  const auto truth = wiggly_path();
  const auto odometry = perturbed(truth, OdometryErrorModel::none(), 7);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_NEAR(odometry[i].x, truth[i].x, 1e-9);
    EXPECT_NEAR(odometry[i].y, truth[i].y, 1e-9);
    EXPECT_NEAR(geometry::angle_difference(odometry[i].yaw, truth[i].yaw), 0, 1e-9);
  }
}

TEST(OdometryPerturber, ScaleErrorAloneScalesAStraightLineExactly) {
  auto model = OdometryErrorModel::none();
  model.translation_scale_error = 0.05;
  const geometry::Pose2 start{2, 3, 0.7};
  const auto odometry = perturbed(straight(start, 10.0, 100), model, 1);
  const auto travelled = start.between(odometry.back());
  EXPECT_NEAR(travelled.x, 10.5, 1e-9);
  EXPECT_NEAR(travelled.y, 0.0, 1e-9);
  EXPECT_NEAR(travelled.yaw, 0.0, 1e-12);
}

TEST(OdometryPerturber, HeadingDriftGrowsWithDistance) {
  auto model = OdometryErrorModel::none();
  model.heading_drift_rad_per_m = 0.01;
  const geometry::Pose2 start{0, 0, 0};
  const auto truth = straight(start, 10.0, 200);
  const auto odometry = perturbed(truth, model, 1);
  for (std::size_t i = 0; i < truth.size(); i += 50) {
    EXPECT_NEAR(odometry[i].yaw - truth[i].yaw, 0.01 * truth[i].x, 1e-9) << i;
  }
  // The odometry curves left: each step's length kept, turned by the drift so far.
  EXPECT_GT(odometry.back().y, 0.4);
  EXPECT_LT(odometry.back().x, 10.0);
}

TEST(OdometryPerturber, RotationScaleErrorScalesTurnsInPlace) {
  auto model = OdometryErrorModel::none();
  model.rotation_scale_error = 0.1;
  std::vector<geometry::Pose2> truth;
  for (int i = 0; i <= 10; ++i) truth.push_back({0, 0, 0.1 * i});
  const auto odometry = perturbed(truth, model, 1);
  EXPECT_NEAR(odometry.back().yaw, 1.1, 1e-9);
  EXPECT_NEAR(odometry.back().x, 0.0, 1e-12);
}

// The length error's variance grows with the distance, not the sample count.
TEST(OdometryPerturber, TranslationNoiseHasTheModelledSpreadAtAnySampling) {
  auto model = OdometryErrorModel::none();
  model.translation_noise_m_per_sqrt_m = 0.02;
  for (const int steps : {4, 40}) {
    const auto truth = straight({0, 0, 0}, 4.0, steps);  // sd 0.02 * sqrt(4) = 0.04 m
    double sum = 0, squares = 0;
    constexpr int kRuns = 4000;
    for (int run = 0; run < kRuns; ++run) {
      const double error = perturbed(truth, model, 1000 + run).back().x - 4.0;
      sum += error;
      squares += error * error;
    }
    const double mean = sum / kRuns;
    const double sd = std::sqrt(squares / kRuns - mean * mean);
    EXPECT_NEAR(mean, 0.0, 0.004) << steps;  // 4 standard errors
    EXPECT_NEAR(sd, 0.04, 0.004) << steps;   // ~10%
  }
}

TEST(OdometryPerturber, SameSeedSameOdometryOtherSeedOther) {
  const auto truth = wiggly_path();
  const OdometryErrorModel model;
  EXPECT_EQ(perturbed(truth, model, 42), perturbed(truth, model, 42));
  EXPECT_NE(perturbed(truth, model, 42), perturbed(truth, model, 43));
  // It starts at the truth.
  EXPECT_EQ(perturbed(truth, model, 42).front(), truth.front());
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string intel_text() {
  auto in = log::open_log_input(radish("intel-corrected.log.gz"));
  std::ostringstream text;
  text << in->rdbuf();
  return text.str();
}

TEST(PerturbLog, IntelKeepsEveryLineButTheOdometryAndKeepsTheTruth) {
  TemporaryDirectory directory;
  std::ostringstream out;
  const auto summary = perturb_log(radish("intel-corrected.log.gz"), out, {}, 5);
  EXPECT_EQ(summary.format, log::LogFormat::kCarmen);
  // 910 FLASER, and the ODOM lines after the first of them (170 come before).
  EXPECT_EQ(summary.odometry_poses_changed, 14541u - 170u + 910u);
  EXPECT_EQ(summary.malformed_lines, 0u);
  EXPECT_NEAR(summary.truth_path_m, 499.5, 0.5);
  EXPECT_DOUBLE_EQ(summary.odometry_input_path_m, summary.truth_path_m);
  EXPECT_GT(summary.final_position_drift_m, 0.5);

  const auto original = lines_of(intel_text());
  const auto degraded = lines_of(out.str());
  ASSERT_EQ(degraded.size(), original.size());
  std::size_t changed = 0;
  for (std::size_t i = 0; i < original.size(); ++i) {
    const auto before = split_line_tokens(original[i]);
    const auto after = split_line_tokens(degraded[i]);
    const bool odom = !before.empty() && before[0].text == "ODOM";
    const bool flaser = !before.empty() && before[0].text == "FLASER";
    if (!odom && !flaser) {
      ASSERT_EQ(degraded[i], original[i]) << "line " << i + 1;
      continue;
    }
    ASSERT_EQ(after.size(), before.size());
    // Only the odometry pose's three tokens may differ.
    const std::size_t first = odom ? 1 : 1 + 1 + 180 + 3;
    for (std::size_t t = 0; t < before.size(); ++t) {
      if (t >= first && t < first + 3) continue;
      ASSERT_EQ(after[t].text, before[t].text) << "line " << i + 1 << " token " << t;
    }
    if (after[first].text != before[first].text) ++changed;
  }
  EXPECT_GT(changed, 14000u);

  // Read back: the same truth, odometry that drifted away from it.
  const auto path = directory.write("intel-noisy.log", out.str());
  LoggedScanReader original_reader(radish("intel-corrected.log.gz"));
  LoggedScanReader degraded_reader(path);
  double largest_drift = 0;
  while (auto want = original_reader.next()) {
    const auto got = degraded_reader.next();
    ASSERT_TRUE(got);
    ASSERT_EQ(got->truth, want->truth);
    ASSERT_EQ(got->ranges, want->ranges);
    largest_drift = std::max(largest_drift, std::hypot(got->odometry->x - got->truth->x,
                                                       got->odometry->y - got->truth->y));
  }
  EXPECT_FALSE(degraded_reader.next());
  EXPECT_GT(largest_drift, 1.0);
}

TEST(PerturbLog, ZeroModelOnIntelChangesNoPoseBeyondPrinting) {
  std::ostringstream out;
  perturb_log(radish("intel-corrected.log.gz"), out, OdometryErrorModel::none(), 5);
  TemporaryDirectory directory;
  LoggedScanReader reader(directory.write("same.log", out.str()));
  while (auto scan = reader.next()) {
    ASSERT_NEAR(scan->odometry->x, scan->truth->x, 2e-6);
    ASSERT_NEAR(scan->odometry->y, scan->truth->y, 2e-6);
    ASSERT_NEAR(geometry::angle_difference(scan->odometry->yaw, scan->truth->yaw), 0, 2e-6);
  }
}

TEST(PerturbLog, CarmenOdomLinesKeepTheirOffsetFromTheLatestScan) {
  TemporaryDirectory directory;
  const auto log = directory.write("robot.log",
                                   "ODOM 0.5 0 0 0 0 0 1 host 1\n"
                                   "FLASER 3 1 2 3 0 0 0 0 0 0 2 host 2\n"
                                   "ODOM 0.5 0 0 0 0 0 3 host 3\n"
                                   "FLASER 3 1 2 3 1 0 0 1 0 0 4 host 4\n"
                                   "ODOM 1.2 0 0.1 0 0 0 5 host 5\n");
  auto model = OdometryErrorModel::none();
  model.translation_scale_error = 0.1;
  std::ostringstream out;
  const auto summary = perturb_log(log, out, model, 3);
  EXPECT_EQ(summary.odometry_poses_changed, 4u);
  EXPECT_DOUBLE_EQ(summary.odometry_input_path_m, 1.0);
  EXPECT_NEAR(summary.final_position_drift_m, 0.1, 1e-12);
  EXPECT_EQ(out.str(),
            "ODOM 0.5 0 0 0 0 0 1 host 1\n"  // before the first scan: as it was
            "FLASER 3 1 2 3 0 0 0 0.000000 0.000000 0.000000 2 host 2\n"
            "ODOM 0.500000 0.000000 0.000000 0 0 0 3 host 3\n"
            "FLASER 3 1 2 3 1 0 0 1.100000 0.000000 0.000000 4 host 4\n"
            "ODOM 1.300000 0.000000 0.100000 0 0 0 5 host 5\n");
}

constexpr const char* kPlayerWithoutTruth =
    "## Player version 1.5 \n"
    "## File version 0.0.0 \n"
    "0000000010.000 robot 6665 position 00 0000000010.000 +01.000 +02.000 +0.500 +00.300 +00.000 +00.000 0\n"
    "0000000010.050 robot 6665 laser 00 0000000010.050 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n"
    "0000000010.100 robot 6665 position 00 0000000010.100 +02.000 +02.000 +0.500 +00.300 +00.000 +00.000 0\n"
    "0000000010.150 robot 6665 laser 00 0000000010.150 -1.5708 +1.5708 +1.5708 0003 4.000  0 5.000  0 6.000  0 \n"
    "0000000010.200 robot 6665 position 00 0000000010.200 +03.000 +02.000 +0.500 +00.300 +00.000 +00.000 0";

TEST(PerturbLog, PlayerLogWithoutTruthGetsTruthLinesWithTheOriginalPoses) {
  TemporaryDirectory directory;
  std::ostringstream out;
  auto model = OdometryErrorModel::none();
  model.translation_scale_error = 0.1;
  const auto summary = perturb_log(directory.write("robot.log", kPlayerWithoutTruth), out, model, 1);
  EXPECT_EQ(summary.format, log::LogFormat::kPlayer);
  EXPECT_EQ(summary.odometry_poses_changed, 3u);
  EXPECT_EQ(summary.truth_lines_added, 3u);
  EXPECT_NEAR(summary.truth_path_m, 2.0, 1e-9);
  EXPECT_NEAR(summary.final_position_drift_m, 0.2, 1e-9);
  EXPECT_EQ(out.str(),
            "## Player version 1.5 \n"
            "## File version 0.0.0 \n"
            "0000000010.000 robot 6665 position 00 0000000010.000 +01.000 +02.000 +0.500 +00.300 +00.000 +00.000 0\n"
            "0000000010.000 robot 6665 truth 00 0000000010.000 +01.000 +02.000 +0.500\n"
            "0000000010.050 robot 6665 laser 00 0000000010.050 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n"
            "0000000010.100 robot 6665 position 00 0000000010.100 +02.100 +02.000 +0.500 +00.300 +00.000 +00.000 0\n"
            "0000000010.100 robot 6665 truth 00 0000000010.100 +02.000 +02.000 +0.500\n"
            "0000000010.150 robot 6665 laser 00 0000000010.150 -1.5708 +1.5708 +1.5708 0003 4.000  0 5.000  0 6.000  0 \n"
            "0000000010.200 robot 6665 position 00 0000000010.200 +03.200 +02.000 +0.500 +00.300 +00.000 +00.000 0\n"
            "0000000010.200 robot 6665 truth 00 0000000010.200 +03.000 +02.000 +0.500");

  // The reader pairs the added truth like any other (latest before the scan).
  LoggedScanReader reader(directory.write("noisy.log", out.str()));
  const auto scan = reader.next();
  ASSERT_TRUE(scan && scan->truth && scan->odometry);
  EXPECT_EQ(*scan->truth, (geometry::Pose2{1.0, 2.0, 0.5}));
  const auto second = reader.next();
  ASSERT_TRUE(second);
  EXPECT_EQ(*second->truth, (geometry::Pose2{2.0, 2.0, 0.5}));
  EXPECT_EQ(*second->odometry, (geometry::Pose2{2.1, 2.0, 0.5}));
}

}  // namespace odometry_perturbation_test
}  // namespace playerkit::localization
