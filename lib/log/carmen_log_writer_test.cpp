// ODOM and FLASER lines written, checked against hand-worked text, and read back.

#include "log/carmen_log_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "log/carmen_log_parser.hpp"
#include "log/carmen_log_reader.hpp"

namespace playerkit::log {
namespace carmen_log_writer_test {

CarmenOdometry sample_odometry() {
  return {{1.5, -2.25, 0.785398}, 0.3, -0.125, 0.05, {1086000000.125, "robot1", 12.5}};
}

CarmenLaser sample_scan() {
  CarmenLaser scan;
  scan.kind = CarmenLaserKind::kFlaser;
  scan.ranges = {1.09, 81.83, 0.23};
  scan.laser_pose = CarmenPose{0.600266, -0.032033, -0.354665};
  scan.robot_pose = CarmenPose{0.61, -0.03, -0.35};
  scan.stamp = {32.906801, "pippo", 32.907};
  return scan;
}

CarmenRecord read_back(const std::string& line) {
  return std::get<CarmenRecord>(parse_carmen_line(line, "written.log", 1));
}

TEST(CarmenWriterTest, WritesOdomAsCarmenDoes) {
  EXPECT_EQ(format_odom(sample_odometry()),
            "ODOM 1.500000 -2.250000 0.785398 0.300000 -0.125000 0.050000 "
            "1086000000.125000 robot1 12.500000\n");
}

TEST(CarmenWriterTest, WritesFlaserAsCarmenDoes) {
  EXPECT_EQ(format_flaser(sample_scan()),
            "FLASER 3 1.090 81.830 0.230 0.600266 -0.032033 -0.354665 0.610000 -0.030000 "
            "-0.350000 32.906801 pippo 32.907000\n");
}

TEST(CarmenWriterTest, OdomRoundTrips) {
  const auto odometry = sample_odometry();
  EXPECT_EQ(std::get<CarmenOdometry>(read_back(format_odom(odometry))), odometry);
}

TEST(CarmenWriterTest, FlaserRoundTripsWithItsGuessedLayout) {
  const auto scan = sample_scan();
  auto back = std::get<CarmenLaser>(read_back(format_flaser(scan)));
  EXPECT_EQ(back.ranges, scan.ranges);
  EXPECT_EQ(back.laser_pose, scan.laser_pose);
  EXPECT_EQ(back.robot_pose, scan.robot_pose);
  EXPECT_EQ(back.stamp, scan.stamp);
  EXPECT_TRUE(back.config_guessed);
  EXPECT_EQ(back.config, guess_carmen_laser_config(3));
}

TEST(CarmenWriterTest, ValuesRoundToTheFilePrecision) {
  auto scan = sample_scan();
  scan.ranges = {1.23456, 2.0004999};
  scan.stamp.ipc_timestamp = 5.12345678;
  auto back = std::get<CarmenLaser>(read_back(format_flaser(scan)));
  EXPECT_EQ(back.ranges, (std::vector<double>{1.235, 2.000}));  // millimetres
  EXPECT_DOUBLE_EQ(back.stamp.ipc_timestamp, 5.123457);        // microseconds
}

TEST(CarmenWriterTest, ARobotLaserBecomesAFlaserWithItsPoses) {
  const auto robot_laser = std::get<CarmenLaser>(read_back(
      "ROBOTLASER1 0 -1.570796 3.141593 0.017453 50 0.1 0 2 3.36 3.34 0 4.775 -5.841 -1.686332 "
      "4.7 -5.8 -1.6 0 0 0 0 0 976053557.767368 x 700.430084"));
  auto back = std::get<CarmenLaser>(read_back(format_flaser(robot_laser)));
  EXPECT_EQ(back.kind, CarmenLaserKind::kFlaser);
  EXPECT_EQ(back.ranges, robot_laser.ranges);
  EXPECT_EQ(back.laser_pose, robot_laser.laser_pose);
  EXPECT_EQ(back.robot_pose, robot_laser.robot_pose);
  EXPECT_EQ(back.stamp, robot_laser.stamp);
}

TEST(CarmenWriterTest, AWrittenLogReadsBackRecordByRecord) {
  std::ostringstream out;
  out << carmen_log_header();
  auto scan = sample_scan();
  auto odometry = sample_odometry();
  for (int i = 0; i < 50; ++i) {
    odometry.pose.x = 0.01 * i;
    odometry.stamp.logger_timestamp = 0.1 * i;
    scan.ranges[0] = 1.0 + 0.001 * i;
    scan.stamp.logger_timestamp = 0.1 * i + 0.05;
    out << format_odom(odometry) << format_flaser(scan);
  }
  std::istringstream in(out.str());
  CarmenLogReader reader(in, "written.log", {.strict = true});
  int odometry_count = 0;
  int scan_count = 0;
  while (auto record = reader.next()) {
    if (auto* read_odometry = std::get_if<CarmenOdometry>(&*record)) {
      EXPECT_DOUBLE_EQ(read_odometry->pose.x, 0.01 * odometry_count);
      ++odometry_count;
    } else {
      EXPECT_DOUBLE_EQ(std::get<CarmenLaser>(*record).ranges[0], 1.0 + 0.001 * scan_count);
      ++scan_count;
    }
  }
  EXPECT_EQ(odometry_count, 50);
  EXPECT_EQ(scan_count, 50);
  EXPECT_EQ(reader.comment_lines(), 6u);
  EXPECT_EQ(reader.unknown_lines(), 0u);
}

TEST(CarmenWriterTest, RefusesWhatWouldNotReadBack) {
  auto odometry = sample_odometry();
  odometry.stamp.host = "two words";
  EXPECT_THROW(format_odom(odometry), std::invalid_argument);
  odometry.stamp.host = "";
  EXPECT_THROW(format_odom(odometry), std::invalid_argument);
  odometry = sample_odometry();
  odometry.tv = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(format_odom(odometry), std::invalid_argument);

  auto scan = sample_scan();
  scan.robot_pose.reset();
  EXPECT_THROW(format_flaser(scan), std::invalid_argument);
  scan = sample_scan();
  scan.ranges[1] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(format_flaser(scan), std::invalid_argument);
}

}  // namespace carmen_log_writer_test
}  // namespace playerkit::log
