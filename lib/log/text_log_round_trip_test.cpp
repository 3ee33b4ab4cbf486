// Writer -> reader -> writer: the same line comes back. Message -> line ->
// message: exactly what the text holds comes back (see text_log_reader.hpp).

#include <gtest/gtest.h>

#include <cstdlib>

#include "log/text_log_reader.hpp"
#include "log/text_log_test_support.hpp"
#include "log/text_log_writer.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/fiducial.hpp"
#include "protocol/messages/gps.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/position3d.hpp"
#include "protocol/messages/sonar.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::log {
namespace text_log_round_trip_test {

using namespace protocol;
using test::data_message;

DataLine read_back(const std::string& line) {
  auto parsed = parse_log_line(line, "round-trip", 1);
  auto* data = std::get_if<DataLine>(&parsed);
  if (data == nullptr) throw std::runtime_error("not a data line: " + line);
  return *data;
}

// The line written again from what the reader made of it.
std::string rewritten(const std::string& line) {
  const auto data = read_back(line);
  return format_data_line(data.message, data.host, data.port);
}

template <class Struct>
Struct through_the_log(std::uint16_t interface, const Struct& value) {
  const auto line = format_data_line(data_message(interface, 0, value), "robot1", 6665);
  return decode<Struct>(read_back(line).message.payload);
}

LaserData sample_scan() {
  LaserData scan;
  scan.min_angle = -12345;
  scan.max_angle = 6789;
  scan.resolution = 25;
  scan.range_res = 10;
  scan.range_count = 4;
  scan.ranges = {100, 250, 4, 6553};
  scan.intensity = {0, 1, 12, 255};
  return scan;
}

TEST(TextLogRoundTrip, EveryInterfaceWithFieldsWritesTheSameLineAgain) {
  PositionData position{1234, -567, 359, 300, -20, -45, 1};
  Position3dData position3d{1000, -2500, 7, 3600, -1800, 324000, 100, 0, -50, 7200, -360000, 36000, 1};
  GpsData gps{4294967295u, 999999, 7355275, -25540639, -71500, 38532100, 376880050, 2, 12, 65535, 2500, 4000};
  TruthData truth{5000, -12345, -179};
  FiducialData fiducial;
  fiducial.count = 2;
  fiducial.fiducials[0] = {7, {1500, 30, -90}, {10, 1, 1}};
  fiducial.fiducials[1] = {-1, {32767, -180, 180}, {0, 0, 0}};
  const std::vector<Message> messages = {
      data_message(kLaserCode, 0, sample_scan()),       data_message(kPositionCode, 3, position),
      data_message(kPosition3dCode, 0, position3d),     data_message(kGpsCode, 0, gps),
      data_message(kTruthCode, 0, truth),               data_message(kFiducialCode, 12, fiducial),
      data_message(kSonarCode, 0, SonarData{}),         data_message(kLaserCode, 1, std::vector<std::uint8_t>{}),
      data_message(kFiducialCode, 0, FiducialData{}),
  };
  for (const auto& message : messages) {
    const auto line = format_data_line(message, "robot1", 6665);
    EXPECT_EQ(rewritten(line), line);
  }
}

TEST(TextLogRoundTrip, SyncLinesReadBackToTheSameLine) {
  const auto line = format_sync_line(1086000000.25, "robot1", 6665);
  const auto parsed = std::get<SyncLine>(parse_log_line(line, "f", 1));
  EXPECT_EQ(format_sync_line(parsed.server_time.seconds(), parsed.host, parsed.port), line);
}

TEST(TextLogRoundTrip, SixDecimalTimesKeepEveryMicrosecond) {
  const auto message =
      data_message(kSonarCode, 0, std::vector<std::uint8_t>{}, {4294967295u, 999999}, {5, 1});
  const auto line = format_data_line(message, "h", 6665);
  EXPECT_EQ(line, "4294967295.999999 h 6665 sonar 00 0000000005.000001 \n");
  const auto back = read_back(line).message;
  EXPECT_EQ(back.time(), (Timestamp{4294967295u, 999999}));
  EXPECT_EQ(back.timestamp(), (Timestamp{5, 1}));
}

TEST(TextLogRoundTrip, ThreeDecimalTimesKeepTheirMilliseconds) {
  const auto message =
      data_message(kSonarCode, 0, std::vector<std::uint8_t>{}, {1086000000, 123456}, {5, 999600});
  const auto back =
      read_back(format_data_line(message, "h", 6665, {.time_decimals = 3})).message;
  EXPECT_EQ(back.time(), (Timestamp{1086000000, 123000}));
  EXPECT_EQ(back.timestamp(), (Timestamp{6, 0}));
}

TEST(TextLogRoundTrip, LaserComesBackWithRangeResOneAndTheSameMetres) {
  const auto back = through_the_log(kLaserCode, sample_scan());
  auto expected = sample_scan();
  expected.range_res = 1;
  expected.ranges = {1000, 2500, 40, 65530};
  EXPECT_EQ(back, expected);
}

TEST(TextLogRoundTrip, LaserAnglesSurviveAllSixteenBitValues) {
  // 4 decimals of a radian are within 0.29 hundredths of a degree, so rounding
  // finds every value again (1.5's truncation lost about half of them).
  LaserData scan;
  for (int angle = -32768; angle <= 32767; ++angle) {
    scan.min_angle = static_cast<std::int16_t>(angle);
    scan.max_angle = static_cast<std::int16_t>(-angle - 1);
    scan.resolution = static_cast<std::uint16_t>(angle + 32768);
    const auto back = through_the_log(kLaserCode, scan);
    ASSERT_EQ(back.min_angle, scan.min_angle);
    ASSERT_EQ(back.max_angle, scan.max_angle);
    ASSERT_EQ(back.resolution, scan.resolution);
  }
}

TEST(TextLogRoundTrip, PositionAndTruthSurviveExactly) {
  for (int degrees = -720; degrees <= 720; ++degrees) {
    PositionData position{-98765, 43210, degrees, 1500, -3, -degrees, 0};
    ASSERT_EQ(through_the_log(kPositionCode, position), position);
    TruthData truth{123456, -654321, degrees};
    ASSERT_EQ(through_the_log(kTruthCode, truth), truth);
  }
}

TEST(TextLogRoundTrip, Position3dAnglesComeBackWithinElevenArcSeconds) {
  // 0.00005 rad is 10.3 arc-seconds.
  for (int arcsec = -1296000; arcsec <= 1296000; arcsec += 997) {
    Position3dData pose{1, 2, 3, arcsec, -arcsec, arcsec / 2, 4, 5, 6, arcsec, arcsec, arcsec, 0};
    const auto back = through_the_log(kPosition3dCode, pose);
    ASSERT_LE(std::abs(back.roll - pose.roll), 11) << arcsec;
    ASSERT_LE(std::abs(back.pitch - pose.pitch), 11) << arcsec;
    ASSERT_LE(std::abs(back.yaw - pose.yaw), 11) << arcsec;
    ASSERT_LE(std::abs(back.yawspeed - pose.yawspeed), 11) << arcsec;
    ASSERT_EQ(back.xpos, 1);
    ASSERT_EQ(back.zspeed, 6);
  }
}

TEST(TextLogRoundTrip, Position3dTinyNegativeAnglesLoseTheirSign) {
  // -5 arc-seconds prints as -0.0000, which reads back as 0 and prints +0.0000:
  // the one place where writing a line read back gives a different line.
  Position3dData pose;
  pose.yaw = -5;
  const auto line = format_data_line(data_message(kPosition3dCode, 0, pose), "robot1", 6665);
  EXPECT_NE(line.find(" -0.0000 +0.0000"), std::string::npos) << line;
  EXPECT_EQ(decode<Position3dData>(read_back(line).message.payload).yaw, 0);
  EXPECT_EQ(rewritten(line), line.substr(0, line.find(" -0.0000 +0.0000")) + " +0.0000" +
                                 line.substr(line.find(" -0.0000 +0.0000") + 8));
}

TEST(TextLogRoundTrip, GpsLosesOnlyTheMicrosecondsOfItsTime) {
  for (std::uint32_t seconds : {0u, 1u, 999999u, 1000000u, 1086000000u, 4294967295u}) {
    GpsData fix{seconds, 654321, -19440000, 38880000, 8848000, -1, 1, 0, 255, 65535, 4294967295u, 0};
    auto expected = fix;
    expected.time_usec = 0;
    ASSERT_EQ(through_the_log(kGpsCode, fix), expected) << seconds;
  }
}

TEST(TextLogRoundTrip, FiducialLosesItsUncertainties) {
  FiducialData seen;
  seen.count = 32;
  for (std::size_t i = 0; i < 32; ++i) {
    const auto n = static_cast<std::int16_t>(i);
    seen.fiducials[i] = {static_cast<std::int16_t>(n - 1), {static_cast<std::int16_t>(n * 1000), static_cast<std::int16_t>(n * 11 - 180), static_cast<std::int16_t>(180 - n * 7)}, {n, n, n}};
  }
  auto expected = seen;
  for (auto& item : expected.fiducials) item.upose = {0, 0, 0};
  EXPECT_EQ(through_the_log(kFiducialCode, seen), expected);
}

}  // namespace text_log_round_trip_test
}  // namespace playerkit::log
