// Lines as Player 1.5's writelog wrote them (logfile-format.md), read back into
// wire structs; the expected wire values are worked out by hand.

#include "log/text_log_reader.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/fiducial.hpp"
#include "protocol/messages/gps.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/position3d.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::log {
namespace text_log_reader_test {

using namespace protocol;

const std::string kPrefix = "1086000000.250 robot1 6665 ";

DataLine data(const std::string& text) {
  auto line = parse_log_line(text, "test.log", 1);
  auto* data = std::get_if<DataLine>(&line);
  if (data == nullptr) throw std::runtime_error("not a data line: " + text);
  return *data;
}

template <class Struct>
Struct payload(const std::string& text) {
  return decode<Struct>(data(text).message.payload);
}

// The error of one line, or a failure when there is none.
LogParseError error_of(const std::string& text, int line_number = 3) {
  try {
    parse_log_line(text, "run.log", line_number);
  } catch (const LogParseError& error) {
    return error;
  }
  throw std::runtime_error("no error for: " + text);
}

TEST(TextLogReader, BlankAndCommentLinesAreSkipped) {
  EXPECT_TRUE(std::holds_alternative<SkippedLine>(parse_log_line("", "f", 1)));
  EXPECT_TRUE(std::holds_alternative<SkippedLine>(parse_log_line("   \t\r\n", "f", 1)));
  EXPECT_TRUE(std::holds_alternative<SkippedLine>(parse_log_line("# written by hand", "f", 1)));
}

TEST(TextLogReader, HeaderLinesGiveNameAndValue) {
  auto line = parse_log_line("## Player version 1.5 \n", "f", 1);
  ASSERT_TRUE(std::holds_alternative<HeaderLine>(line));
  EXPECT_EQ(std::get<HeaderLine>(line).name, "Player version");
  EXPECT_EQ(std::get<HeaderLine>(line).value, "1.5");
  line = parse_log_line("## File version 0.0.0 ", "f", 2);
  EXPECT_EQ(std::get<HeaderLine>(line).name, "File version");
  EXPECT_EQ(std::get<HeaderLine>(line).value, "0.0.0");
  EXPECT_EQ(std::get<HeaderLine>(line).value_column, 17);
  EXPECT_EQ(error_of("## ").message(), "a '##' header line needs a name and a value");
  EXPECT_EQ(error_of("## ").column(), 4);
}

TEST(TextLogReader, SyncLine) {
  auto line = parse_log_line("1086000000.250 robot1 6665 sync 00 1086000000.250 \n", "f", 1);
  ASSERT_TRUE(std::holds_alternative<SyncLine>(line));
  const auto& sync = std::get<SyncLine>(line);
  EXPECT_EQ(sync.server_time, (Timestamp{1086000000, 250000}));
  EXPECT_EQ(sync.data_time, (Timestamp{1086000000, 250000}));
  EXPECT_EQ(sync.host, "robot1");
  EXPECT_EQ(sync.port, 6665);
}

TEST(TextLogReader, PrefixGivesTimesHostPortAndDevice) {
  const auto line = data("1086000001.500 robot1 7000 laser 02 1086000000.001 ");
  EXPECT_EQ(line.server_time, (Timestamp{1086000001, 500000}));
  EXPECT_EQ(line.data_time, (Timestamp{1086000000, 1000}));
  EXPECT_EQ(line.host, "robot1");
  EXPECT_EQ(line.port, 7000);
  EXPECT_EQ(line.interface_name, "laser");
  EXPECT_EQ(line.index, 2);
  EXPECT_EQ(line.device, (DeviceAddress{kLaserCode, 2}));
  const auto& header = line.message.header;
  EXPECT_EQ(header.stx, kStx);
  EXPECT_EQ(header.type, static_cast<std::uint16_t>(MessageType::kData));
  EXPECT_EQ(line.message.device(), (DeviceAddress{kLaserCode, 2}));
  EXPECT_EQ(line.message.time(), line.server_time);
  EXPECT_EQ(line.message.timestamp(), line.data_time);
}

TEST(TextLogReader, TimestampsAreReadAsExactDecimals) {
  // 1086000000.123 is not a double; 1.5 truncated it to ...122999 us.
  EXPECT_EQ(data("1086000000.123 h 6665 sonar 00 0000000007.999 ").server_time,
            (Timestamp{1086000000, 123000}));
  EXPECT_EQ(data("1086000000.123 h 6665 sonar 00 0000000007.999 ").data_time, (Timestamp{7, 999000}));
  // More digits than the writer gives round to the microsecond.
  EXPECT_EQ(data("1.0000005 h 6665 sonar 00 2 ").server_time, (Timestamp{1, 1}));
  EXPECT_EQ(data("1.9999996 h 6665 sonar 00 2 ").server_time, (Timestamp{2, 0}));
  EXPECT_EQ(data("1.9999996 h 6665 sonar 00 2 ").data_time, (Timestamp{2, 0}));
}

TEST(TextLogReader, LaserComesBackInMillimetresWithRangeResOne) {
  const auto scan = payload<LaserData>(kPrefix + "laser 00 1086000000.125 "
                                                 "-1.5708 +1.5708 +0.0087 0003 1.000  0 2.500  1 0.040 12 ");
  EXPECT_EQ(scan.min_angle, -9000);
  EXPECT_EQ(scan.max_angle, 9000);
  EXPECT_EQ(scan.resolution, 50);  // rounded: 1.5's truncation gave 49
  EXPECT_EQ(scan.range_res, 1);
  ASSERT_EQ(scan.range_count, 3);
  EXPECT_EQ(scan.ranges[0], 1000);
  EXPECT_EQ(scan.ranges[1], 2500);
  EXPECT_EQ(scan.ranges[2], 40);
  EXPECT_EQ(scan.intensity[0], 0);
  EXPECT_EQ(scan.intensity[1], 1);
  EXPECT_EQ(scan.intensity[2], 12);
  EXPECT_EQ(scan.ranges[3], 0);
}

TEST(TextLogReader, LaserRangesRoundToTheNearestMillimetre) {
  // atof("1.001") * 1000 is 1000.9999999999999: 1.5 stored 1000.
  const auto scan = payload<LaserData>(kPrefix + "laser 00 1.000 +0.0000 +0.0000 +0.0175 0001 1.001  0 ");
  EXPECT_EQ(scan.ranges[0], 1001);
  EXPECT_EQ(scan.resolution, 100);
}

TEST(TextLogReader, LaserRangesBeyond65MetresTakeACoarserRangeRes) {
  auto scan = payload<LaserData>(kPrefix + "laser 00 1.000 +0.0000 +0.0000 +0.0175 0002 80.000  0 0.120  0 ");
  EXPECT_EQ(scan.range_res, 10);
  EXPECT_EQ(scan.ranges[0], 8000);
  EXPECT_EQ(scan.ranges[1], 12);
  scan = payload<LaserData>(kPrefix + "laser 00 1.000 +0.0000 +0.0000 +0.0175 0001 700.000  0 ");
  EXPECT_EQ(scan.range_res, 100);
  EXPECT_EQ(scan.ranges[0], 7000);
}

TEST(TextLogReader, Position) {
  const auto pose =
      payload<PositionData>(kPrefix + "position 02 1.000 +01.234 -00.567 +1.571 +00.300 +00.000 -00.785 1");
  EXPECT_EQ(pose.xpos, 1234);
  EXPECT_EQ(pose.ypos, -567);
  EXPECT_EQ(pose.yaw, 90);
  EXPECT_EQ(pose.xspeed, 300);
  EXPECT_EQ(pose.yspeed, 0);
  EXPECT_EQ(pose.yawspeed, -45);
  EXPECT_EQ(pose.stall, 1);  // 1.5's readlog left stall unread
}

TEST(TextLogReader, Position3dAnglesComeBackToTheNearestArcSecond) {
  const auto pose = payload<Position3dData>(kPrefix + "position3d 00 1.000 "
                                                      "+1.0000 -2.5000 +0.0000 +0.0175 -0.0087 +1.5708 "
                                                      "+0.1000 +0.0000 -0.0500 +0.0000 +0.0000 +0.1745 1");
  EXPECT_EQ(pose.xpos, 1000);
  EXPECT_EQ(pose.ypos, -2500);
  EXPECT_EQ(pose.zpos, 0);
  EXPECT_EQ(pose.roll, 3610);     // 0.0175 rad
  EXPECT_EQ(pose.pitch, -1795);   // -0.0087 rad
  EXPECT_EQ(pose.yaw, 324001);    // 1.5708 rad
  EXPECT_EQ(pose.xspeed, 100);
  EXPECT_EQ(pose.zspeed, -50);
  EXPECT_EQ(pose.yawspeed, 35993);  // 0.1745 rad/s
  EXPECT_EQ(pose.stall, 1);
}

TEST(TextLogReader, GpsUndoesTheTimeQuirk) {
  const auto fix = payload<GpsData>(kPrefix + "gps 00 1.000 "
                                              "1086001086.000 34.052199 -118.243699 71.500000 385321.000 "
                                              "3768800.500 1.200 2.500 4.000 1 7");
  EXPECT_EQ(fix.time_sec, 1086000000u);  // 1086001086 / (1 + 1e-6)
  EXPECT_EQ(fix.time_usec, 0u);
  EXPECT_EQ(fix.latitude, 7355275);
  EXPECT_EQ(fix.longitude, -25540639);
  EXPECT_EQ(fix.altitude, 71500);
  EXPECT_EQ(fix.utm_e, 38532100);
  EXPECT_EQ(fix.utm_n, 376880050);
  EXPECT_EQ(fix.hdop, 12);
  EXPECT_EQ(fix.err_horz, 2500u);
  EXPECT_EQ(fix.err_vert, 4000u);
  EXPECT_EQ(fix.quality, 1);
  EXPECT_EQ(fix.num_sats, 7);
}

TEST(TextLogReader, Truth) {
  const auto pose = payload<TruthData>(kPrefix + "truth 00 1.000 +05.000 -12.345 +3.142");
  EXPECT_EQ(pose.px, 5000);
  EXPECT_EQ(pose.py, -12345);
  EXPECT_EQ(pose.pa, 180);
}

TEST(TextLogReader, FiducialUncertaintiesComeBackZero) {
  const auto seen = payload<FiducialData>(kPrefix + "fiducial 00 1.000 "
                                                    "2 7 +01.500 +00.524 -1.571 -1 +00.250 -00.175 +0.000");
  ASSERT_EQ(seen.count, 2);
  EXPECT_EQ(seen.fiducials[0].id, 7);
  EXPECT_EQ(seen.fiducials[0].pose, (std::array<std::int16_t, 3>{1500, 30, -90}));
  EXPECT_EQ(seen.fiducials[0].upose, (std::array<std::int16_t, 3>{0, 0, 0}));
  EXPECT_EQ(seen.fiducials[1].id, -1);
  EXPECT_EQ(seen.fiducials[1].pose, (std::array<std::int16_t, 3>{250, -10, 0}));
  EXPECT_EQ(payload<FiducialData>(kPrefix + "fiducial 00 1.000 0").count, 0);
}

TEST(TextLogReader, PrefixOnlyLinesHaveAnEmptyPayload) {
  for (std::string name : {"laser", "position", "gps", "sonar", "wifi"}) {
    const auto line = data(kPrefix + name + " 01 1086000000.125 \n");
    EXPECT_TRUE(line.message.payload.empty()) << name;
    EXPECT_EQ(line.message.header.size, 0u) << name;
    ASSERT_TRUE(line.device.has_value()) << name;
    EXPECT_EQ(interface_name(line.device->interface), name);
  }
}

TEST(TextLogReader, UnknownInterfacesHaveNoDeviceAndAnEmptyPayload) {
  const auto line = data(kPrefix + "lazer 00 1086000000.125 1 2 3");
  EXPECT_EQ(line.interface_name, "lazer");
  EXPECT_FALSE(line.device.has_value());
  EXPECT_TRUE(line.message.payload.empty());
  EXPECT_EQ(line.message.header.device, 0);
}

TEST(TextLogReader, ErrorsNameFileLineAndColumn) {
  const auto error = error_of("1086000000.250 robot1 66x5 laser 00 1.000 ", 3);
  EXPECT_EQ(error.file(), "run.log");
  EXPECT_EQ(error.line(), 3);
  EXPECT_EQ(error.column(), 23);
  EXPECT_EQ(std::string(error.what()), "run.log:3:23: port: expected a whole number, got '66x5'");
}

TEST(TextLogReader, MalformedPrefixes) {
  EXPECT_EQ(error_of("abc robot1 6665 laser 00 1.000").column(), 1);
  EXPECT_EQ(error_of("-1.000 robot1 6665 laser 00 1.000").column(), 1);
  EXPECT_EQ(error_of("1.000 robot1 6665 laser 00 1.").column(), 28);
  EXPECT_EQ(error_of("99999999999.000 robot1 6665 laser 00 1.000").column(), 1);
  EXPECT_EQ(error_of("1.000 robot1 70000 laser 00 1.000").column(), 14);
  EXPECT_EQ(error_of("1.000 robot1 6665 laser x 1.000").column(), 25);
  const auto short_line = error_of("1.000 robot1 6665");
  EXPECT_EQ(short_line.column(), 18);  // just past the end
  EXPECT_NE(short_line.message().find("line ends before the data time"), std::string::npos)
      << short_line.message();
  EXPECT_EQ(error_of("1.000 robot1 6665 sync 00 1.000 extra").column(), 33);
}

TEST(TextLogReader, MalformedLaserLines) {
  const std::string laser = kPrefix + "laser 00 1.000 ";  // fields start at column 43
  EXPECT_EQ(error_of(laser + "+0.0000").column(), 50);  // ends before max_angle
  EXPECT_EQ(error_of(laser + "+0.0000 +0.0000 +0.0175 0500").column(), 67);
  auto missing = error_of(laser + "+0.0000 +0.0000 +0.0175 0003 1.000  0 2.000  1 ");
  EXPECT_EQ(missing.message(), "laser line ends after 2 of its 3 readings (each is a range and an intensity)");
  EXPECT_EQ(missing.column(), 90);
  EXPECT_EQ(error_of(laser + "+0.0000 +0.0000 +0.0175 0001 1.000  0 2.000").column(), 81);
  EXPECT_EQ(error_of(laser + "+0.0000 +0.0000 +0.0175 0001 -1.000  0").column(), 72);
  EXPECT_EQ(error_of(laser + "+0.0000 +0.0000 +0.0175 0001 1.000 256").column(), 78);
  EXPECT_EQ(error_of(laser + "+0.0000 +0.0000 +0.0175 0001 7000.000 0").column(), 72);
  EXPECT_EQ(error_of(laser + "+9.0000 +0.0000 +0.0175 0000").message(),
            "min_angle: +9.0000 is 51566 0.01 deg, outside the wire field's -32768..32767");
}

TEST(TextLogReader, MalformedFieldsOfOtherInterfaces) {
  const std::string at = "1.000 h 6665 ";  // position and fiducial fields from column 32, truth and sonar from 29
  EXPECT_EQ(error_of(at + "position 00 1.000 +0.000 +0.000 +0.000 +0.000 +0.000 +0.000").column(), 73);
  EXPECT_EQ(error_of(at + "position 00 1.000 +0.000 +0.000 +0.000 +0.000 +0.000 +0.000 1 9").column(), 76);
  EXPECT_EQ(error_of(at + "position 00 1.000 +3000000.000 +0.000 +0.000 +0.000 +0.000 +0.000 1").column(), 32);
  EXPECT_EQ(error_of(at + "truth 00 1.000 +0.000 zero +0.000").column(), 36);
  EXPECT_EQ(error_of(at + "truth 00 1.000 +0.000 nan +0.000").column(), 36);
  EXPECT_EQ(error_of(at + "fiducial 00 1.000 2 7 +01.500 +00.524 -1.571").column(), 58);
  EXPECT_EQ(error_of(at + "fiducial 00 1.000 33").column(), 32);
  const auto audio = error_of(at + "audio 00 1.000 1.000 2.000");
  EXPECT_EQ(audio.column(), 29);
  EXPECT_EQ(audio.message(), "audio lines carry no data fields in a text log");
}

TEST(TextLogReader, ReadsAWholeFileLineByLine) {
  std::istringstream in("## Player version 1.5 \n"
                        "## File version 0.0.0 \n"
                        "1086000000.200 robot1 6665 position 00 1086000000.150 "
                        "+01.000 +00.000 +0.000 +00.000 +00.000 +00.000 0\n"
                        "# a comment\n"
                        "\n"
                        "1086000000.250 robot1 6665 sync 00 1086000000.250 \n");
  TextLogReader reader(in, "run.log");
  auto first = reader.next();
  ASSERT_TRUE(first.has_value());
  ASSERT_TRUE(std::holds_alternative<DataLine>(*first));
  EXPECT_EQ(decode<PositionData>(std::get<DataLine>(*first).message.payload).xpos, 1000);
  EXPECT_EQ(reader.line_number(), 3);
  EXPECT_EQ(reader.player_version(), "1.5");
  EXPECT_EQ(reader.file_version(), "0.0.0");
  auto second = reader.next();
  ASSERT_TRUE(second.has_value());
  EXPECT_TRUE(std::holds_alternative<SyncLine>(*second));
  EXPECT_EQ(reader.line_number(), 6);
  EXPECT_FALSE(reader.next().has_value());
}

TEST(TextLogReader, AnErrorGivesTheLineAndTheReaderGoesOn) {
  std::istringstream in("## Player version 1.5 \n"
                        "1.000 h 6665 sync 00 1.000 \n"
                        "1.100 h 6665 truth 00 1.000 +0.000\n"
                        "1.200 h 6665 sync 00 1.200 \n");
  TextLogReader reader(in, "run.log", {.strict = true});
  EXPECT_TRUE(reader.next().has_value());
  try {
    reader.next();
    FAIL() << "no error";
  } catch (const LogParseError& error) {
    EXPECT_EQ(std::string(error.what()), "run.log:3:35: line ends before y");
  }
  auto after = reader.next();
  ASSERT_TRUE(after.has_value());
  EXPECT_EQ(std::get<SyncLine>(*after).server_time, (Timestamp{1, 200000}));
}

TEST(TextLogReader, RejectsOtherFileVersions) {
  std::istringstream in("## Player version 2.0.4 \n## File version 0.3.0 \n");
  TextLogReader reader(in, "new.log");
  try {
    reader.next();
    FAIL() << "no error";
  } catch (const LogParseError& error) {
    EXPECT_EQ(error.line(), 2);
    EXPECT_EQ(error.column(), 17);
    EXPECT_NE(error.message().find("file version 0.3.0"), std::string::npos) << error.message();
  }
}

}  // namespace text_log_reader_test
}  // namespace playerkit::log
