// truth_from_log: a Player log's truth samples at their own times.

#include "localization/trajectory.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "localization/localization_test_support.hpp"
#include "localization/trajectory_evaluation.hpp"

namespace playerkit::localization {
namespace trajectory_test {

using testing::TemporaryDirectory;

// A recording of a simulated robot driving +x at 1 m/s: position and truth
// every 0.1 s, a scan every 0.2 s; the truth of 10.2 s was not recorded, so
// the scan of 10.2 s carries the truth of 10.1 s.
constexpr const char* kLostTruth =
    "## Player version 1.5 \n"
    "## File version 0.0.0 \n"
    "0000000010.000 sim 6665 position 00 0000000010.000 +01.000 +02.000 +0.000 +00.000 +00.000 +00.000 0\n"
    "0000000010.000 sim 6665 laser 00 0000000010.000 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n"
    "0000000010.000 sim 6665 truth 00 0000000010.000 +05.000 +06.000 +0.000\n"
    "0000000010.100 sim 6665 position 00 0000000010.100 +01.100 +02.000 +0.000 +00.000 +00.000 +00.000 0\n"
    "0000000010.100 sim 6665 truth 00 0000000010.100 +05.100 +06.000 +0.000\n"
    "0000000010.200 sim 6665 position 00 0000000010.200 +01.200 +02.000 +0.000 +00.000 +00.000 +00.000 0\n"
    "0000000010.200 sim 6665 laser 00 0000000010.200 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n"
    "0000000010.300 sim 6665 position 00 0000000010.300 +01.300 +02.000 +0.000 +00.000 +00.000 +00.000 0\n"
    "0000000010.300 sim 6665 truth 00 0000000010.300 +05.300 +06.000 +0.000\n"
    "0000000010.400 sim 6665 laser 00 0000000010.400 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n"
    "0000000010.400 sim 6665 truth 00 0000000010.400 +05.400 +06.000 +0.000\n"
    "0000000010.400 sim 6665 truth 01 0000000010.400 +09.000 +09.000 +0.000\n";

TEST(TruthFromLog, APlayerLogsTruthSamplesAtTheirOwnTimes) {
  TemporaryDirectory directory;
  const auto log = directory.write("sim.log", kLostTruth);
  const Trajectory truth = truth_from_log(log);
  ASSERT_EQ(truth.size(), 4u);  // truth:1 is another robot's
  const std::vector<double> times{10.0, 10.1, 10.3, 10.4};
  const std::vector<double> xs{5.0, 5.1, 5.3, 5.4};
  for (std::size_t i = 0; i < truth.size(); ++i) {
    EXPECT_DOUBLE_EQ(truth[i].time, times[i]);
    EXPECT_DOUBLE_EQ(truth[i].pose.x, xs[i]);
    EXPECT_DOUBLE_EQ(truth[i].pose.y, 6.0);
  }

  // The scans alone would say 5.1 at 10.2 s; the samples around it say 5.2.
  LoggedScanReader reader(log);
  reader.next();
  EXPECT_DOUBLE_EQ(reader.next()->truth->x, 5.1);
  const Trajectory exact{{10.0, {5.0, 6.0, 0.0}}, {10.2, {5.2, 6.0, 0.0}}, {10.4, {5.4, 6.0, 0.0}}};
  const auto result = evaluate_trajectory(exact, truth);
  EXPECT_EQ(result.matched, 3u);
  EXPECT_NEAR(result.all.position_max_m, 0.0, 1e-9);
}

TEST(TruthFromLog, OnTruthSeesEverySampleOfTheLasersIndex) {
  TemporaryDirectory directory;
  std::vector<double> seen;
  LoggedScanReaderOptions options;
  options.laser_index = 1;
  options.on_truth = [&seen](double time, const geometry::Pose2& pose) {
    seen.push_back(time);
    EXPECT_DOUBLE_EQ(pose.x, 9.0);
  };
  LoggedScanReader reader(directory.write("sim.log", kLostTruth), options);
  while (reader.next()) {
  }
  EXPECT_EQ(seen, (std::vector<double>{10.4}));
}

}  // namespace trajectory_test
}  // namespace playerkit::localization
