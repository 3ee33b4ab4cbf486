// LoggedScanReader on the bundled intel log (CARMEN), the same log converted to
// a Player log, and small handwritten Player logs.

#include "localization/logged_scan_reader.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "localization/localization_test_support.hpp"
#include "log/carmen_log_reader.hpp"
#include "log/log_conversion.hpp"
#include "log/log_input.hpp"
#include "log/log_parse_error.hpp"
#include "log/text_log_writer.hpp"

namespace playerkit::localization {
namespace logged_scan_reader_test {

using testing::radish;
using testing::TemporaryDirectory;

std::vector<LoggedScan> read_all(LoggedScanReader& reader) {
  std::vector<LoggedScan> scans;
  while (auto scan = reader.next()) scans.push_back(std::move(*scan));
  return scans;
}

TEST(LoggedScanReader, IntelCarmenLogHasEveryScanWithBothPoses) {
  LoggedScanReader reader(radish("intel-corrected.log.gz"));
  EXPECT_EQ(reader.format(), log::LogFormat::kCarmen);
  const auto scans = read_all(reader);
  ASSERT_EQ(scans.size(), 910u);
  EXPECT_EQ(reader.scans_without_odometry(), 0u);
  EXPECT_EQ(reader.scans_without_truth(), 0u);
  EXPECT_EQ(reader.malformed_lines(), 0u);
  // Scan times mostly rise; four times a scan is stamped up to 0.9 s before
  // the one above it (the log's own stamps, kept as they are).
  double previous_time = -1;
  std::size_t backwards = 0;
  for (const auto& scan : scans) {
    ASSERT_EQ(scan.ranges.size(), 180u);
    ASSERT_TRUE(scan.odometry && scan.truth);
    if (scan.time < previous_time) {
      ++backwards;
      EXPECT_LT(previous_time - scan.time, 0.9);
    }
    previous_time = scan.time;
    // SLAM-corrected: FLASER's odom fields repeat its laser pose.
    EXPECT_EQ(*scan.odometry, *scan.truth);
  }
  EXPECT_EQ(backwards, 4u);
  // The first FLASER: "... 0.600266 -0.0320327 -0.354665 ... 32.9068 pippo 32.9068".
  EXPECT_DOUBLE_EQ(scans[0].time, 32.9068);
  EXPECT_DOUBLE_EQ(scans[0].truth->x, 0.600266);
  EXPECT_DOUBLE_EQ(scans[0].truth->y, -0.0320327);
  EXPECT_DOUBLE_EQ(scans[0].truth->yaw, -0.354665);
  EXPECT_DOUBLE_EQ(scans[0].ranges[0], 1.09);
  // 180 beams: 1 deg steps from -90 deg; no PARAM, so CARMEN's 80 m guess,
  // below the 81.83 m no-return readings.
  EXPECT_NEAR(scans[0].angle_min, -std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(scans[0].angle_increment, std::numbers::pi / 180, 1e-12);
  EXPECT_DOUBLE_EQ(scans[0].max_range, 80.0);
}

TEST(LoggedScanReader, MaxRangeComesFromTheFrontLaserParam) {
  LoggedScanReader reader(radish("csail-corrected.log.gz"));  // PARAM robot_front_laser_max 50
  const auto scan = reader.next();
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->ranges.size(), 361u);
  EXPECT_DOUBLE_EQ(scan->max_range, 50.0);
}

TEST(LoggedScanReader, OtherLaserIndexOfACarmenLogHasNoScans) {
  LoggedScanReader reader(radish("intel-corrected.log.gz"), {.laser_index = 1});
  EXPECT_FALSE(reader.next());
}

// intel -> Player messages -> a Player text log, as `player-log convert` does.
std::filesystem::path intel_as_player_log(const TemporaryDirectory& directory) {
  const auto path = directory.path() / "intel.log";
  std::ofstream out(path);
  out << log::log_file_header();
  auto in = log::open_log_input(radish("intel-corrected.log.gz"));
  log::CarmenLogReader carmen(*in, "intel");
  while (auto record = carmen.next()) {
    const auto converted = log::carmen_to_player(*record);
    for (const auto& message : converted.messages) out << log::format_data_line(message, converted.host, 6665);
  }
  return path;
}

TEST(LoggedScanReader, IntelAsPlayerLogGivesTheSameScansWithinPlayerPrecision) {
  TemporaryDirectory directory;
  const auto player_log = intel_as_player_log(directory);
  LoggedScanReader carmen(radish("intel-corrected.log.gz"));
  LoggedScanReader player(player_log);
  EXPECT_EQ(player.format(), log::LogFormat::kPlayer);
  const auto expected = read_all(carmen);
  const auto actual = read_all(player);
  ASSERT_EQ(actual.size(), expected.size());
  EXPECT_EQ(player.scans_without_odometry(), 0u);
  EXPECT_EQ(player.scans_without_truth(), 0u);
  EXPECT_EQ(player.malformed_lines(), 0u);
  // Player's wire units: mm, whole degrees (the pose quantum of carmen_to_player),
  // then written as 3 decimals of a radian; ranges in cm when a no-return
  // reading needs range_res 10.
  constexpr double kHalfDegree = std::numbers::pi / 360 + 0.0005 + 1e-9;
  for (std::size_t i = 0; i < actual.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_NEAR(actual[i].time, expected[i].time, 1e-6);
    ASSERT_EQ(actual[i].ranges.size(), expected[i].ranges.size());
    for (std::size_t b = 0; b < actual[i].ranges.size(); ++b) {
      ASSERT_NEAR(actual[i].ranges[b], expected[i].ranges[b], 0.005 + 1e-9);
    }
    EXPECT_NEAR(actual[i].angle_min, expected[i].angle_min, 1e-9);
    EXPECT_NEAR(actual[i].angle_increment, expected[i].angle_increment, 1e-9);
    for (const auto& [got, want] : {std::pair{*actual[i].odometry, *expected[i].odometry},
                                    std::pair{*actual[i].truth, *expected[i].truth}}) {
      EXPECT_NEAR(got.x, want.x, 0.0005 + 1e-9);
      EXPECT_NEAR(got.y, want.y, 0.0005 + 1e-9);
      EXPECT_NEAR(geometry::angle_difference(got.yaw, want.yaw), 0.0, kHalfDegree);
    }
  }
}

// Laser and position with their own times, as a real robot logs them.
constexpr const char* kIndependentTimes =
    "## Player version 1.5 \n"
    "## File version 0.0.0 \n"
    "0000000010.000 robot 6665 position 00 0000000010.000 +01.000 +02.000 +0.500 +00.000 +00.000 +00.000 0\n"
    "0000000010.050 robot 6665 laser 00 0000000010.050 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0 \n"
    "0000000010.100 robot 6665 position 00 0000000010.100 +01.100 +02.000 +0.600 +00.000 +00.000 +00.000 0\n"
    "0000000010.120 robot 6665 laser 01 0000000010.120 -1.5708 +1.5708 +1.5708 0003 9.000  0 9.000  0 9.000  0 \n"
    "0000000010.150 robot 6665 laser 00 0000000010.150 -1.5708 +1.5708 +1.5708 0003 4.000  0 5.000  0 6.000  0 \n"
    "0000000010.160 robot 6665 truth 00 0000000010.150 +05.000 +06.000 +0.700\n"
    "0000000010.170 robot 6665 position 00 0000000010.150 +01.200 +02.000 +0.650 +00.000 +00.000 +00.000 0\n"
    "this line is not a log line\n"
    "0000000010.200 robot 6665 position 00 0000000010.200 +01.300 +02.000 +0.700 +00.000 +00.000 +00.000 0\n"
    "0000000010.250 robot 6665 laser 00 0000000010.250 -1.5708 +1.5708 +1.5708 0003 7.000  0 8.000  0 90.000  0 \n";

TEST(LoggedScanReader, PlayerLogWithIndependentTimesTakesLatestOrSameTimePoses) {
  TemporaryDirectory directory;
  LoggedScanReader reader(directory.write("robot.log", kIndependentTimes), {.default_max_range = 8.0});
  const auto scans = read_all(reader);
  ASSERT_EQ(scans.size(), 3u);
  EXPECT_EQ(reader.malformed_lines(), 1u);

  // The first scan: the latest position before it; no truth yet.
  EXPECT_DOUBLE_EQ(scans[0].time, 10.05);
  EXPECT_EQ(scans[0].ranges, (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_NEAR(scans[0].angle_min, -std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(scans[0].angle_increment, std::numbers::pi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(scans[0].max_range, 8.0);
  EXPECT_EQ(scans[0].odometry, (geometry::Pose2{1.0, 2.0, 0.5}));
  EXPECT_FALSE(scans[0].truth);

  // The second: truth and position at its data time follow it (laser:1 ignored).
  EXPECT_EQ(scans[1].ranges, (std::vector<double>{4.0, 5.0, 6.0}));
  EXPECT_EQ(scans[1].odometry, (geometry::Pose2{1.2, 2.0, 0.65}));
  EXPECT_EQ(scans[1].truth, (geometry::Pose2{5.0, 6.0, 0.7}));

  // The third: latest position (10.2) and the latest truth, both before it.
  EXPECT_EQ(scans[2].odometry, (geometry::Pose2{1.3, 2.0, 0.7}));
  EXPECT_EQ(scans[2].truth, (geometry::Pose2{5.0, 6.0, 0.7}));
  EXPECT_DOUBLE_EQ(scans[2].ranges[2], 90.0);
}

TEST(LoggedScanReader, StrictPlayerReaderThrowsOnTheBadLine) {
  TemporaryDirectory directory;
  LoggedScanReader reader(directory.write("robot.log", kIndependentTimes), {.strict = true});
  EXPECT_TRUE(reader.next());
  EXPECT_TRUE(reader.next());
  try {
    reader.next();
    FAIL() << "no error";
  } catch (const log::LogParseError& error) {
    EXPECT_EQ(error.line(), 10);
  }
}

TEST(LoggedScanReader, ScanBeforeAnyPositionHasNoOdometry) {
  TemporaryDirectory directory;
  LoggedScanReader reader(directory.write("robot.log",
                                          "0000000010.050 robot 6665 laser 00 0000000010.050 -1.5708 +1.5708 "
                                          "+1.5708 0003 1.000  0 2.000  0 3.000  0 \n"));
  ASSERT_TRUE(reader.next());
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.scans_without_odometry(), 1u);
}

TEST(LoggedScanReader, UnreadableOrForeignFilesAreClearErrors) {
  TemporaryDirectory directory;
  EXPECT_THROW(LoggedScanReader(directory.path() / "missing.log"), std::runtime_error);
  try {
    LoggedScanReader reader(directory.write("notes.txt", "hello world\n"));
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("notes.txt:1: neither a Player log line"), std::string::npos)
        << error.what();
  }
}

}  // namespace logged_scan_reader_test
}  // namespace playerkit::localization
