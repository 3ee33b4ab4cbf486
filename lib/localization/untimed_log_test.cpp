// The Örebro log (tests/data/radish, PROVENANCE.md): no usable times at all.
// Scans come in file order on the synthetic clock, perturbation keeps the
// file's order, and estimates are matched to the truth by scan order.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "localization/localization_test_support.hpp"
#include "localization/logged_scan_reader.hpp"
#include "localization/odometry_perturbation.hpp"
#include "localization/scan_order_matching.hpp"
#include "localization/trajectory.hpp"
#include "log/log_clock.hpp"
#include "log/log_input.hpp"

namespace playerkit::localization {
namespace untimed_log_test {

const auto kOrebro = testing::radish("orebro-corrected.log.gz");

std::string gunzipped(const std::filesystem::path& path) {
  auto in = log::open_log_input(path);
  std::ostringstream text;
  text << in->rdbuf();
  return text.str();
}

// x y theta of every ODOM line, in file order.
std::vector<std::array<double, 3>> odometry_poses(const std::string& log_text) {
  std::vector<std::array<double, 3>> poses;
  std::istringstream in(log_text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("ODOM ", 0) != 0) continue;
    std::istringstream fields(line.substr(5));
    std::array<double, 3> pose{};
    fields >> pose[0] >> pose[1] >> pose[2];
    poses.push_back(pose);
  }
  return poses;
}

std::vector<std::string> keywords(const std::string& log_text) {
  std::vector<std::string> words;
  std::istringstream in(log_text);
  for (std::string line; std::getline(in, line);) words.push_back(line.substr(0, line.find(' ')));
  return words;
}

TEST(UntimedLog, OrebroScansComeInFileOrderOnTheSyntheticClock) {
  LoggedScanReader reader(kOrebro);
  EXPECT_TRUE(reader.clock().synthetic());
  EXPECT_EQ(reader.clock().records(), 492u);  // 255 ODOM + 237 FLASER, every one stamped unusably
  std::vector<double> times;
  while (auto scan = reader.next()) {
    EXPECT_EQ(scan->ranges.size(), 181u);
    times.push_back(scan->time);
  }
  ASSERT_EQ(times.size(), 237u);
  // The log opens with ODOM, FLASER, ODOM, FLASER: the first scans are records 1 and 3.
  EXPECT_DOUBLE_EQ(times[0], 1 / log::LogClock::kSyntheticRateHz);
  EXPECT_DOUBLE_EQ(times[1], 3 / log::LogClock::kSyntheticRateHz);
  for (std::size_t i = 1; i < times.size(); ++i) EXPECT_GT(times[i], times[i - 1]) << i;
}

TEST(UntimedLog, PerturbingOrebroWithoutErrorsKeepsEveryLineInItsPlace) {
  std::ostringstream out;
  const auto summary = perturb_log(kOrebro, out, OdometryErrorModel::none(), 1);
  EXPECT_EQ(summary.format, log::LogFormat::kCarmen);
  EXPECT_NEAR(summary.final_position_drift_m, 0.0, 1e-5);
  EXPECT_NEAR(summary.final_heading_drift_rad, 0.0, 1e-5);
  EXPECT_GT(summary.truth_path_m, 200.0);  // the robot does move: 221 m of corrected path

  const std::string original = gunzipped(kOrebro);
  EXPECT_EQ(keywords(out.str()), keywords(original));  // the same records in the same order
  const auto before = odometry_poses(original);
  const auto after = odometry_poses(out.str());
  ASSERT_EQ(before.size(), 255u);
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_NEAR(after[i][0], before[i][0], 1e-5) << i;  // CARMEN's %f
    EXPECT_NEAR(after[i][1], before[i][1], 1e-5) << i;
    EXPECT_NEAR(std::remainder(after[i][2] - before[i][2], 2 * M_PI), 0.0, 1e-5) << i;  // written in (-pi, pi]
  }
}

TEST(UntimedLog, TheTruthOfOrebroIsInScanOrder) {
  const auto truth = truth_from_log(kOrebro);
  ASSERT_EQ(truth.size(), 237u);
  for (std::size_t i = 1; i < truth.size(); ++i) EXPECT_GT(truth[i].time, truth[i - 1].time) << i;
}

TEST(ScanOrderMatching, RowKGetsTheTimeOfTruthPoseK) {
  const Trajectory truth{{0.1, {0, 0, 0}}, {0.3, {1, 0, 0}}, {0.5, {2, 0, 0}}};
  const Trajectory estimate{{0, {0.1, 0, 0}}, {0, {1.1, 0, 0}}, {0, {2.1, 0, 0}}};  // all stamped 0
  const auto retimed = retimed_by_scan_order(estimate, truth);
  ASSERT_EQ(retimed.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(retimed[k].time, truth[k].time);
    EXPECT_EQ(retimed[k].pose.x, estimate[k].pose.x);
  }
  EXPECT_THROW(retimed_by_scan_order({estimate[0]}, truth), std::invalid_argument);
}

}  // namespace untimed_log_test
}  // namespace playerkit::localization
