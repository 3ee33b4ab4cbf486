// CARMEN lines written by hand in the field orders of CARMEN's logger
// (carmen_log.hpp), parsed into records whose expected values are read off the
// line.

#include "log/carmen_log_parser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace playerkit::log {
namespace carmen_log_parser_test {

constexpr double kPi = std::numbers::pi;

CarmenRecord record(const std::string& text) {
  auto line = parse_carmen_line(text, "test.log", 7);
  auto* parsed = std::get_if<CarmenRecord>(&line);
  if (parsed == nullptr) throw std::runtime_error("not a record: " + text);
  return *parsed;
}

template <class Record>
Record as(const std::string& text) {
  return std::get<Record>(record(text));
}

// The error a line gives, or a test failure when it gives none.
LogParseError error_of(const std::string& text) {
  try {
    parse_carmen_line(text, "run.log", 12);
  } catch (const LogParseError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for: " << text;
  return LogParseError("", 0, 0, "");
}

TEST(CarmenLineTest, ReadsParam) {
  const auto param = as<CarmenParam>("PARAM robot_frontlaser_offset -0.04 1071078718.462310 merci 1071078718.462309");
  EXPECT_EQ(param.name, "robot_frontlaser_offset");
  EXPECT_EQ(param.value, "-0.04");
  EXPECT_DOUBLE_EQ(param.stamp.ipc_timestamp, 1071078718.462310);
  EXPECT_EQ(param.stamp.host, "merci");
  EXPECT_DOUBLE_EQ(param.stamp.logger_timestamp, 1071078718.462309);
}

TEST(CarmenLineTest, ParamValueKeepsItsInnerSpaces) {
  const auto param = as<CarmenParam>("PARAM robot_name my  big robot 0 nohost 0");
  EXPECT_EQ(param.value, "my big robot");
  EXPECT_EQ(param.stamp.host, "nohost");
}

TEST(CarmenLineTest, ReadsParamWithRadishsShortStamp) {
  // Edmonton, Freiburg 101 and Intel write `name value host logger_timestamp`.
  const auto on = as<CarmenParam>("PARAM robot_allow_rear_motion on nohost 0");
  EXPECT_EQ(on.name, "robot_allow_rear_motion");
  EXPECT_EQ(on.value, "on");
  EXPECT_EQ(on.stamp.host, "nohost");
  EXPECT_EQ(on.stamp.ipc_timestamp, 0.0);
  EXPECT_EQ(on.stamp.logger_timestamp, 0.0);
  const auto number = as<CarmenParam>("PARAM robot_frontlaser_offset 0.0 nohost 12.5");
  EXPECT_EQ(number.value, "0.0");  // a value, not an ipc timestamp with the value left empty
  EXPECT_EQ(number.stamp.ipc_timestamp, 12.5);
  EXPECT_NE(error_of("PARAM robot_use_laser on nohost later").message().find("logger timestamp"), std::string::npos);
}

TEST(CarmenLineTest, ReadsOdometry) {
  const auto odometry = as<CarmenOdometry>("ODOM 1.5 -2.25 0.785398 0.3 -0.1 0.05 32.9068 pippo 33.0001\n");
  EXPECT_EQ(odometry.pose, (CarmenPose{1.5, -2.25, 0.785398}));
  EXPECT_DOUBLE_EQ(odometry.tv, 0.3);
  EXPECT_DOUBLE_EQ(odometry.rv, -0.1);
  EXPECT_DOUBLE_EQ(odometry.acceleration, 0.05);
  EXPECT_EQ(odometry.stamp, (CarmenStamp{32.9068, "pippo", 33.0001}));
}

TEST(CarmenLineTest, ReadsExponentTimesAsTheCsailLogHasThem) {
  const auto odometry = as<CarmenOdometry>("ODOM 0 0 0 0 0 0 1.13486e+09 pippo 1.13486e+09\r\n");
  EXPECT_DOUBLE_EQ(odometry.stamp.ipc_timestamp, 1134860000.0);
  EXPECT_DOUBLE_EQ(odometry.stamp.logger_timestamp, 1134860000.0);
}

TEST(CarmenLineTest, ReadsTruePos) {
  const auto true_pos = as<CarmenTruePos>("TRUEPOS 1 2 0.5 1.1 2.2 0.6 10.5 sim 10.75");
  EXPECT_EQ(true_pos.true_pose, (CarmenPose{1, 2, 0.5}));
  EXPECT_EQ(true_pos.odometry_pose, (CarmenPose{1.1, 2.2, 0.6}));
  EXPECT_EQ(true_pos.stamp, (CarmenStamp{10.5, "sim", 10.75}));
}

TEST(CarmenLineTest, ReadsFlaserWithBothPosesAndAGuessedLayout) {
  const auto laser = as<CarmenLaser>("FLASER 4 1.09 1.08 81.83 0.23 0.600266 -0.0320327 -0.354665 "
                                     "0.61 -0.03 -0.35 32.9068 pippo 32.9070");
  EXPECT_EQ(laser.kind, CarmenLaserKind::kFlaser);
  EXPECT_EQ(laser.ranges, (std::vector<double>{1.09, 1.08, 81.83, 0.23}));
  EXPECT_TRUE(laser.remissions.empty());
  EXPECT_EQ(laser.laser_pose, (CarmenPose{0.600266, -0.0320327, -0.354665}));
  EXPECT_EQ(laser.robot_pose, (CarmenPose{0.61, -0.03, -0.35}));
  EXPECT_FALSE(laser.motion);
  EXPECT_EQ(laser.stamp, (CarmenStamp{32.9068, "pippo", 32.9070}));
  EXPECT_TRUE(laser.config_guessed);
  EXPECT_DOUBLE_EQ(laser.config.start_angle, -kPi / 2);
  EXPECT_DOUBLE_EQ(laser.config.angular_resolution, kPi / 3);  // 4 beams evenly over 180 deg
  EXPECT_DOUBLE_EQ(laser.config.fov, kPi);
}

TEST(CarmenLineTest, RlaserHasTheFlaserLayout) {
  const auto laser = as<CarmenLaser>("RLASER 2 3.5 4.5 1 2 3 4 5 6 7 host 8");
  EXPECT_EQ(laser.kind, CarmenLaserKind::kRlaser);
  EXPECT_EQ(laser.ranges, (std::vector<double>{3.5, 4.5}));
  EXPECT_EQ(laser.laser_pose, (CarmenPose{1, 2, 3}));
  EXPECT_EQ(laser.robot_pose, (CarmenPose{4, 5, 6}));
  EXPECT_EQ(laser.stamp, (CarmenStamp{7, "host", 8}));
}

TEST(CarmenLineTest, ReadsOldLaser3WithoutPoses) {
  const auto laser = as<CarmenLaser>("LASER3 3 1 2 3 7 host 8");
  EXPECT_EQ(laser.kind, CarmenLaserKind::kLaser3);
  EXPECT_EQ(laser.ranges, (std::vector<double>{1, 2, 3}));
  EXPECT_FALSE(laser.laser_pose);
  EXPECT_FALSE(laser.robot_pose);
}

TEST(CarmenLineTest, GuessesTheSickLayoutsOfTheRadishLogs) {
  const auto deg = kPi / 180;
  const auto l180 = guess_carmen_laser_config(180);
  EXPECT_DOUBLE_EQ(l180.angular_resolution, 1 * deg);
  EXPECT_DOUBLE_EQ(l180.fov, 179 * deg);  // last beam at +89 deg
  const auto l360 = guess_carmen_laser_config(360);
  EXPECT_DOUBLE_EQ(l360.angular_resolution, 0.5 * deg);
  EXPECT_DOUBLE_EQ(l360.fov, 179.5 * deg);
  const auto l361 = guess_carmen_laser_config(361);
  EXPECT_DOUBLE_EQ(l361.angular_resolution, 0.5 * deg);
  EXPECT_DOUBLE_EQ(l361.fov, 180 * deg);
  EXPECT_DOUBLE_EQ(l361.start_angle, -90 * deg);
  EXPECT_DOUBLE_EQ(l361.maximum_range, 80.0);
}

TEST(CarmenLineTest, ReadsRawLaserWithRemissions) {
  const auto laser = as<CarmenLaser>("RAWLASER2 2 -2.0944 4.18879 0.00613 5.6 0.01 1 "
                                     "3 0.5 0.75 1.25 2 100 200.5 12.5 urg 12.75");
  EXPECT_EQ(laser.kind, CarmenLaserKind::kRawLaser2);
  EXPECT_EQ(laser.config, (CarmenLaserConfig{2, -2.0944, 4.18879, 0.00613, 5.6, 0.01, 1}));
  EXPECT_FALSE(laser.config_guessed);
  EXPECT_EQ(laser.ranges, (std::vector<double>{0.5, 0.75, 1.25}));
  EXPECT_EQ(laser.remissions, (std::vector<double>{100, 200.5}));
  EXPECT_FALSE(laser.laser_pose);
  EXPECT_EQ(laser.stamp, (CarmenStamp{12.5, "urg", 12.75}));
}

TEST(CarmenLineTest, ReadsEveryRawLaserNumber) {
  for (const std::string keyword : {"RAWLASER1", "RAWLASER3", "RAWLASER4"}) {
    const auto laser = as<CarmenLaser>(keyword + " 0 -1.5708 3.14159 0.0174533 80 0.01 0 1 2.5 0 1 h 2");
    EXPECT_EQ(carmen_laser_keyword(laser.kind), keyword);
    EXPECT_EQ(laser.ranges, std::vector<double>{2.5});
  }
}

// The first ROBOTLASER1 line of flirtlib's intel-lab.log, shortened to 3 beams.
const std::string kRobotLaser =
    "ROBOTLASER1 0 -1.570796 3.141593 0.017453 50.000000 0.100000 0 3 81.83 3.36 3.34 0 "
    "4.775000 -5.841000 -1.686332 4.775000 -5.841000 -1.686332 0.000000 0.000000 0.000000 "
    "0.000000 0.000000 976053557.767368 x 700.430084";

TEST(CarmenLineTest, ReadsRobotLaserWithTurnAxis) {
  const auto laser = as<CarmenLaser>(kRobotLaser);
  EXPECT_EQ(laser.kind, CarmenLaserKind::kRobotLaser1);
  EXPECT_EQ(laser.config, (CarmenLaserConfig{0, -1.570796, 3.141593, 0.017453, 50, 0.1, 0}));
  EXPECT_EQ(laser.ranges, (std::vector<double>{81.83, 3.36, 3.34}));
  EXPECT_TRUE(laser.remissions.empty());
  EXPECT_EQ(laser.laser_pose, (CarmenPose{4.775, -5.841, -1.686332}));
  EXPECT_EQ(laser.robot_pose, (CarmenPose{4.775, -5.841, -1.686332}));
  EXPECT_EQ(laser.motion, (CarmenLaserMotion{0, 0, 0, 0, 0.0}));
  EXPECT_EQ(laser.stamp, (CarmenStamp{976053557.767368, "x", 700.430084}));
}

TEST(CarmenLineTest, ReadsOlderRobotLaserWithoutTurnAxisAndWithRemissions) {
  const auto laser = as<CarmenLaser>("ROBOTLASER2 4 -2.35 4.7 0.5 30 0.02 2 2 1.5 2.5 2 0.25 0.75 "
                                     "1 2 3 4 5 6 0.4 -0.2 0.6 0.3 99.5 s300 100.25");
  EXPECT_EQ(laser.kind, CarmenLaserKind::kRobotLaser2);
  EXPECT_EQ(laser.remissions, (std::vector<double>{0.25, 0.75}));
  EXPECT_EQ(laser.laser_pose, (CarmenPose{1, 2, 3}));
  EXPECT_EQ(laser.robot_pose, (CarmenPose{4, 5, 6}));
  ASSERT_TRUE(laser.motion);
  EXPECT_DOUBLE_EQ(laser.motion->tv, 0.4);
  EXPECT_DOUBLE_EQ(laser.motion->rv, -0.2);
  EXPECT_DOUBLE_EQ(laser.motion->forward_safety_dist, 0.6);
  EXPECT_DOUBLE_EQ(laser.motion->side_safety_dist, 0.3);
  EXPECT_FALSE(laser.motion->turn_axis);
  EXPECT_EQ(laser.stamp, (CarmenStamp{99.5, "s300", 100.25}));
}

TEST(CarmenLineTest, CommentsAndBlankLinesAreBlank) {
  for (const std::string text : {"", "   ", "# CARMEN Logfile", "#SEQUENTIAL EDGES", "\r\n"}) {
    EXPECT_TRUE(std::holds_alternative<CarmenBlankLine>(parse_carmen_line(text, "f", 1))) << text;
  }
}

TEST(CarmenLineTest, UnknownKeywordsAreNamed) {
  for (const std::string keyword : {"NEFF", "VERTEX2", "EDGE2", "SYNC", "flaser"}) {
    const auto line = parse_carmen_line(keyword + " 1 2 3", "f", 1);
    ASSERT_TRUE(std::holds_alternative<CarmenUnknownLine>(line)) << keyword;
    EXPECT_EQ(std::get<CarmenUnknownLine>(line).keyword, keyword);
  }
}

TEST(CarmenLineTest, ABadNumberNamesItsFieldAndColumn) {
  const auto error = error_of("ODOM 1 2 abc 0 0 0 1 h 1");
  EXPECT_EQ(error.line(), 12);
  EXPECT_EQ(error.column(), 10);
  EXPECT_STREQ(error.what(), "run.log:12:10: odometry theta: expected a number, got 'abc'");
}

TEST(CarmenLineTest, ABadReadingIsNamedByItsIndex) {
  // FLASER n r0..r(n-1) laser pose, odometry pose, ipc timestamp, host, logger timestamp
  EXPECT_EQ(error_of("FLASER 3 1.0 2.0 x 0 0 0 0 0 0 1 h 1").message(), "range 2: expected a number, got 'x'");
  EXPECT_EQ(error_of("FLASER 2 1.0 2.0 0 0 0 0 0 ? 1 h 1").message(), "odometry theta: expected a number, got '?'");
}

TEST(CarmenLineTest, NonFiniteNumbersAreErrors) {
  EXPECT_EQ(error_of("ODOM nan 0 0 0 0 0 1 h 1").message(), "odometry x: expected a number, got 'nan'");
  EXPECT_EQ(error_of("ODOM 0 0 0 inf 0 0 1 h 1").message(), "tv: expected a number, got 'inf'");
}

TEST(CarmenLineTest, AShortLineSaysWhatIsMissing) {
  EXPECT_EQ(error_of("ODOM 1 2 3 0 0 0 5.5 pippo").message(), "line ends before logger timestamp");
  EXPECT_EQ(error_of("PARAM name 0 host").message(),
            "line ends before the ipc timestamp, host, logger timestamp of PARAM name");
}

TEST(CarmenLineTest, ExtraFieldsAreErrors) {
  const auto error = error_of("ODOM 1 2 3 0 0 0 5.5 pippo 5.5 extra");
  EXPECT_EQ(error.message(), "unexpected field 'extra' after the logger timestamp");
  EXPECT_EQ(error.column(), 32);
}

TEST(CarmenLineTest, AFlaserCountThatDisagreesWithItsFieldsIsAnError) {
  // 3 readings announced, 2 given: without the check the poses would shift.
  const auto error = error_of("FLASER 3 1.0 2.0 1 2 3 4 5 6 7 host 8");
  EXPECT_EQ(error.column(), 8);
  EXPECT_EQ(error.message(),
            "3 readings announced, but 11 fields follow (expected 3 readings then 9: laser pose, "
            "odometry pose, ipc timestamp, host, logger timestamp)");
  EXPECT_EQ(error_of("FLASER -1 1 2 3 4 5 6 7 host 8").message(), "number of readings is negative: -1");
  EXPECT_EQ(error_of("FLASER 2.5 1 2 3 4 5 6 7 host 8").message(),
            "number of readings: expected a whole number, got '2.5'");
}

TEST(CarmenLineTest, ARobotLaserWithTooManyTrailingFieldsIsAnError) {
  const auto error = error_of(kRobotLaser + " 1");
  EXPECT_EQ(error.message(),
            "0 remissions announced, but 15 fields follow (expected 0 remissions then 13 or 14: "
            "laser pose, robot pose, tv, rv, forward_safety_dist, side_safety_dist, [turn_axis], "
            "ipc timestamp, host, logger timestamp)");
}

TEST(CarmenLineTest, ARawLaserWithoutRemissionCountIsAnError) {
  const auto error = error_of("RAWLASER1 0 -1.5 3.1 0.01 80 0.01 0 2 1 2 1 h");
  EXPECT_EQ(error.message(),
            "2 readings announced, but 4 fields follow (expected 2 readings then at least 4: "
            "num_remissions, remissions, ipc timestamp, host, logger timestamp)");
}

}  // namespace carmen_log_parser_test
}  // namespace playerkit::log
