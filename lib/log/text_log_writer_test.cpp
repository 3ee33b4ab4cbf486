// Golden lines: each expected string was worked out by hand from the printf
// patterns of logfile-format.md (§2, §3) and the wire units of the structs.

#include "log/text_log_writer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "log/text_log_test_support.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/fiducial.hpp"
#include "protocol/messages/gps.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/position3d.hpp"
#include "protocol/messages/sonar.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::log {
namespace text_log_writer_test {

using namespace protocol;
using test::data_message;

// These golden lines are byte-exact Player 1.5 output: 3-decimal times.
constexpr TextLogWriterOptions kPlayer15{.version = LogFormatVersion::k0_0_0, .time_decimals = 3};

// "%014.3f %s %d %s %02d %014.3f " with the test messages' two times.
std::string prefix(std::string_view interface, std::string_view index) {
  return std::string("1086000000.250 robot1 6665 ").append(interface).append(" ").append(index).append(
      " 1086000000.125 ");
}

TEST(TextLogWriter, HeaderIsTwoLinesWithTrailingSpaces) {
  EXPECT_EQ(log_file_header(), "## Player version 1.5 \n## File version 0.0.0 \n");
}

TEST(TextLogWriter, SyncLineIsThePrefixWithTheSameTimeTwice) {
  EXPECT_EQ(format_sync_line(1086000000.25, "robot1", 6665, kPlayer15),
            "1086000000.250 robot1 6665 sync 00 1086000000.250 \n");
}

TEST(TextLogWriter, TimesAreZeroPaddedToFourteenCharacters) {
  EXPECT_EQ(format_sync_line(12.5, "h", 7000, kPlayer15), "0000000012.500 h 7000 sync 00 0000000012.500 \n");
  EXPECT_EQ(format_sync_line(0.0, "h", 7000, kPlayer15), "0000000000.000 h 7000 sync 00 0000000000.000 \n");
}

TEST(TextLogWriter, TokenZeroIsTheHeaderTimeAndTokenFiveTheTimestamp) {
  auto message = data_message(kSonarCode, 0, std::vector<std::uint8_t>{}, {1086000001, 500000},
                              {1086000000, 1000});
  EXPECT_EQ(format_data_line(message, "robot1", 6665, kPlayer15),
            "1086000001.500 robot1 6665 sonar 00 1086000000.001 \n");
}

TEST(TextLogWriter, TimesRoundToMillisecondsAndCarryIntoTheSeconds) {
  auto message = data_message(kSonarCode, 0, std::vector<std::uint8_t>{}, {5, 999600}, {7, 123456});
  EXPECT_EQ(format_data_line(message, "h", 6665, kPlayer15), "0000000006.000 h 6665 sonar 00 0000000007.123 \n");
}

TEST(TextLogWriter, IndexHasAtLeastTwoDigits) {
  EXPECT_EQ(format_data_line(data_message(kSonarCode, 7, std::vector<std::uint8_t>{}), "robot1", 6665, kPlayer15),
            prefix("sonar", "07") + "\n");
  EXPECT_EQ(format_data_line(data_message(kSonarCode, 123, std::vector<std::uint8_t>{}), "robot1", 6665, kPlayer15),
            prefix("sonar", "123") + "\n");
}

TEST(TextLogWriter, LaserGivesAnglesInRadiansAndRangesInMetresTimesRangeRes) {
  LaserData scan;
  scan.min_angle = -9000;  // -90 deg
  scan.max_angle = 9000;
  scan.resolution = 50;  // 0.5 deg = 0.0087266 rad: only 4 decimals survive
  scan.range_res = 10;
  scan.range_count = 3;
  scan.ranges[0] = 100;  // 100 x 10 mm = 1 m
  scan.ranges[1] = 250;
  scan.ranges[2] = 4;
  scan.intensity = {0, 1, 12};
  EXPECT_EQ(format_data_line(data_message(kLaserCode, 0, scan), "robot1", 6665, kPlayer15),
            prefix("laser", "00") +
                "-1.5708 +1.5708 +0.0087 0003 1.000  0 2.500  1 0.040 12 \n");
}

// The reading loop formats without printf; printf's "%.3f %2d " of
// mm / 1000.0 is the reference it must match, over the whole range of both
// wire fields (ranges and range_res are 16-bit, intensity 8-bit).
TEST(TextLogWriter, ReadingsMatchPrintfOverTheWholeWireRange) {
  const std::vector<std::uint16_t> range_resolutions{1, 10, 100, 7, 65535};
  std::uint32_t state = 12345;  // a fixed LCG: the same readings every run
  for (const std::uint16_t range_res : range_resolutions) {
    for (int round = 0; round < 200; ++round) {
      LaserData scan;
      scan.resolution = 100;
      scan.range_res = range_res;
      scan.range_count = 401;
      std::string expected = prefix("laser", "00") + "+0.0000 +0.0000 +0.0175 0401 ";
      for (std::size_t i = 0; i < scan.range_count; ++i) {
        state = state * 1664525u + 1013904223u;
        // Edges first (0, 999, 1000, 65535), then anything.
        const std::uint16_t edges[] = {0, 1, 9, 999, 1000, 1001, 65534, 65535};
        scan.ranges[i] = round == 0 && i < 8 ? edges[i] : static_cast<std::uint16_t>(state >> 16);
        scan.intensity[i] = static_cast<std::uint8_t>(round == 0 ? i : state >> 8);
        char reading[64];
        std::snprintf(reading, sizeof reading, "%.3f %2d ",
                      static_cast<double>(std::uint32_t{scan.ranges[i]} * range_res) / 1000.0,
                      static_cast<int>(scan.intensity[i]));
        expected += reading;
      }
      ASSERT_EQ(format_data_line(data_message(kLaserCode, 0, scan), "robot1", 6665, kPlayer15), expected + "\n")
          << "range_res " << range_res << ", round " << round;
    }
  }
}

TEST(TextLogWriter, LaserWithoutReadingsStillEndsWithASpace) {
  LaserData scan;
  scan.resolution = 100;
  scan.range_res = 1;
  EXPECT_EQ(format_data_line(data_message(kLaserCode, 1, scan), "robot1", 6665, kPlayer15),
            prefix("laser", "01") + "+0.0000 +0.0000 +0.0175 0000 \n");
}

TEST(TextLogWriter, PositionGivesMetresAndRadiansWithSignsAndZeroPadding) {
  PositionData pose;
  pose.xpos = 1234;
  pose.ypos = -567;
  pose.yaw = 90;  // %+04.3f: width 4 never pads
  pose.xspeed = 300;
  pose.yspeed = 0;
  pose.yawspeed = -45;
  pose.stall = 1;
  EXPECT_EQ(format_data_line(data_message(kPositionCode, 2, pose), "robot1", 6665, kPlayer15),
            prefix("position", "02") + "+01.234 -00.567 +1.571 +00.300 +00.000 -00.785 1\n");
}

TEST(TextLogWriter, Position3dGivesFourDecimalsAndArcSecondsAsRadians) {
  Position3dData pose;
  pose.xpos = 1000;
  pose.ypos = -2500;
  pose.roll = 3600;      // 1 deg
  pose.pitch = -1800;    // -0.5 deg
  pose.yaw = 324000;     // 90 deg
  pose.xspeed = 100;
  pose.zspeed = -50;
  pose.yawspeed = 36000;  // 10 deg/s
  EXPECT_EQ(format_data_line(data_message(kPosition3dCode, 0, pose), "robot1", 6665, kPlayer15),
            prefix("position3d", "00") +
                "+1.0000 -2.5000 +0.0000 +0.0175 -0.0087 +1.5708 "
                "+0.1000 +0.0000 -0.0500 +0.0000 +0.0000 +0.1745 0\n");
}

TEST(TextLogWriter, GpsKeepsTheTimeQuirkOfTimeSecTwice) {
  GpsData fix;
  fix.time_sec = 1086000000;
  fix.time_usec = 500000;  // not written: 1.5 adds time_sec * 1e-6 instead
  fix.latitude = 7355275;     // 34.052199... deg
  fix.longitude = -25540639;  // -118.243699... deg
  fix.altitude = 71500;
  fix.utm_e = 38532100;
  fix.utm_n = 376880050;
  fix.quality = 1;
  fix.num_sats = 7;
  fix.hdop = 12;
  fix.err_horz = 2500;
  fix.err_vert = 4000;
  EXPECT_EQ(format_data_line(data_message(kGpsCode, 0, fix), "robot1", 6665, kPlayer15),
            prefix("gps", "00") +
                "1086001086.000 34.052199 -118.243699 71.500000 385321.000 3768800.500 "
                "1.200 2.500 4.000 1 7\n");
}

TEST(TextLogWriter, TruthGivesPoseInMetresAndRadians) {
  TruthData pose;
  pose.px = 5000;
  pose.py = -12345;
  pose.pa = 180;
  EXPECT_EQ(format_data_line(data_message(kTruthCode, 0, pose), "robot1", 6665, kPlayer15),
            prefix("truth", "00") + "+05.000 -12.345 +3.142\n");
}

TEST(TextLogWriter, FiducialGivesCountThenIdRangeBearingOrientation) {
  FiducialData seen;
  seen.count = 2;
  seen.fiducials[0].id = 7;
  seen.fiducials[0].pose = {1500, 30, -90};
  seen.fiducials[0].upose = {10, 1, 1};  // uncertainties are not written
  seen.fiducials[1].id = -1;
  seen.fiducials[1].pose = {250, -10, 0};
  EXPECT_EQ(format_data_line(data_message(kFiducialCode, 0, seen), "robot1", 6665, kPlayer15),
            prefix("fiducial", "00") + "2 7 +01.500 +00.524 -1.571 -1 +00.250 -00.175 +0.000\n");
}

TEST(TextLogWriter, FiducialWithNothingSeenIsJustTheCount) {
  EXPECT_EQ(format_data_line(data_message(kFiducialCode, 0, FiducialData{}), "robot1", 6665, kPlayer15),
            prefix("fiducial", "00") + "0\n");
}

TEST(TextLogWriter, InterfacesWithoutFieldsGetThePrefixOnly) {
  // A wifi message without links has no groups to write (1.5's readlog format).
  EXPECT_EQ(format_data_line(data_message(kWifiCode, 1, std::vector<std::uint8_t>(658, 0)), "robot1", 6665, kPlayer15),
            prefix("wifi", "01") + "\n");
  EXPECT_EQ(format_data_line(data_message(kNullCode, 0, std::vector<std::uint8_t>{1, 2, 3}), "robot1", 6665, kPlayer15),
            prefix("null", "00") + "\n");
}

TEST(TextLogWriter, AZeroLengthPayloadGetsThePrefixOnlyEvenForLaser) {
  EXPECT_EQ(format_data_line(data_message(kLaserCode, 0, std::vector<std::uint8_t>{}), "robot1", 6665, kPlayer15),
            prefix("laser", "00") + "\n");
}

TEST(TextLogWriter, APayloadThatDoesNotFitItsStructIsADecodeError) {
  EXPECT_THROW(format_data_line(data_message(kLaserCode, 0, std::vector<std::uint8_t>(900, 0)), "h", 6665, kPlayer15),
               DecodeError);
  EXPECT_THROW(format_data_line(data_message(kPositionCode, 0, std::vector<std::uint8_t>(30, 0)), "h", 6665, kPlayer15),
               DecodeError);
}

TEST(TextLogWriter, RejectsWhatTheFormatCannotHold) {
  auto not_data = data_message(kLaserCode, 0, LaserData{});
  not_data.header.type = static_cast<std::uint16_t>(MessageType::kCommand);
  EXPECT_THROW(format_data_line(not_data, "h", 6665, kPlayer15), std::invalid_argument);
  EXPECT_THROW(format_data_line(data_message(99, 0, std::vector<std::uint8_t>{}), "h", 6665, kPlayer15),
               std::invalid_argument);
  EXPECT_THROW(format_data_line(data_message(kSonarCode, 0, std::vector<std::uint8_t>{}), "two words", 6665, kPlayer15),
               std::invalid_argument);
  EXPECT_THROW(format_sync_line(1.0, "", 6665, kPlayer15), std::invalid_argument);
}

TEST(TextLogWriter, TheErrorNamesTheProblem) {
  try {
    format_data_line(data_message(99, 0, std::vector<std::uint8_t>{}), "h", 6665, kPlayer15);
    FAIL() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("interface code 99"), std::string::npos) << error.what();
  }
}

}  // namespace text_log_writer_test
}  // namespace playerkit::log
