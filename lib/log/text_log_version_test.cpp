// Format 0.2.0 (spec §6) and playerkit's extension interfaces: golden lines
// worked out by hand from the printf patterns in lib/log/README.md, then
// round trips of every interface in both versions.

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>

#include "log/text_log_reader.hpp"
#include "log/text_log_test_support.hpp"
#include "log/text_log_writer.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"

namespace playerkit::log {
namespace text_log_version_test {

using namespace protocol;
using test::data_message;

constexpr TextLogWriterOptions kV0{.version = LogFormatVersion::k0_0_0, .time_decimals = 6};
constexpr TextLogWriterOptions kV2{.version = LogFormatVersion::k0_2_0, .time_decimals = 6};

std::string prefix(std::string_view interface) {
  return std::string("1086000000.250000 robot1 6665 ").append(interface).append(" 00 1086000000.125000 ");
}

template <class Struct>
std::string line_of(std::uint16_t interface, const Struct& value, const TextLogWriterOptions& options) {
  return format_data_line(data_message(interface, 0, value), "robot1", 6665, options);
}

DataLine read_back(const std::string& line, LogFormatVersion version) {
  auto parsed = parse_log_line(line, "v", 1, version);
  auto* data = std::get_if<DataLine>(&parsed);
  if (data == nullptr) throw std::runtime_error("not a data line: " + line);
  return *data;
}

// ---- samples ----

LaserData sample_laser() {
  LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 25;
  scan.range_res = 1;
  scan.range_count = 2;
  scan.ranges = {1000, 2500};
  scan.intensity = {5, 0};
  return scan;
}

TruthData sample_truth() { return {1500, -250, 90}; }

FiducialData sample_fiducial() {
  FiducialData seen;
  seen.count = 1;
  seen.fiducials[0].id = 7;
  seen.fiducials[0].pose = {2000, 90, -90};
  seen.fiducials[0].upose = {100, 2, 0};
  return seen;
}

GpsData sample_gps() {
  GpsData fix;
  fix.time_sec = 1086000000;
  fix.latitude = 7355275;
  fix.longitude = -25540639;
  fix.altitude = 71500;
  fix.utm_e = 38532100;
  fix.utm_n = 376880050;
  fix.quality = 1;
  fix.num_sats = 7;
  fix.hdop = 12;
  fix.err_horz = 2500;
  fix.err_vert = 4000;
  return fix;
}

WifiData sample_wifi() {
  WifiData wifi;
  wifi.link_count = 2;
  wifi.links[0] = {"192.168.0.1", 40, 200, 150};
  wifi.links[1] = {"", 1, 2, 3};
  return wifi;
}

SonarData sample_sonar() {
  SonarData sonar;
  sonar.range_count = 3;
  sonar.ranges[0] = 1000;
  sonar.ranges[1] = 250;
  sonar.ranges[2] = 65535;
  return sonar;
}

IrData sample_ir() {
  IrData ir;
  ir.range_count = 2;
  ir.ranges[0] = 120;
  ir.ranges[1] = 3000;
  ir.voltages[0] = 512;
  ir.voltages[1] = 7;
  return ir;
}

BumperData sample_bumper() {
  BumperData bumper;
  bumper.bumper_count = 3;
  bumper.bumpers[1] = 1;
  return bumper;
}

LocalizeData sample_localize(bool with_covariance) {
  LocalizeData localize;
  localize.pending_count = 2;
  localize.pending_time_sec = 1086000000;
  localize.pending_time_usec = 5;
  localize.hypoth_count = 1;
  localize.hypoths[0].mean = {1500, -2000, 3600};
  localize.hypoths[0].alpha = 500000;
  if (with_covariance) {
    localize.hypoths[0].cov = {{{10000, -3, 77}, {-3, 2500000000LL, 0}, {77, 0, 1296000000LL}}};
  }
  return localize;
}

BlobfinderData sample_blobfinder() {
  BlobfinderData seen;
  seen.width = 320;
  seen.height = 240;
  // Channel 0 and 2 hold one blob each; every index is the running offset.
  seen.header[0] = {0, 1};
  seen.header[1] = {1, 0};
  seen.header[2] = {1, 1};
  for (std::size_t c = 3; c < seen.header.size(); ++c) seen.header[c] = {2, 0};
  seen.blobs.push_back({0xff0000, 100, 10, 20, 5, 15, 15, 25, 1500});
  seen.blobs.push_back({0x0000ff, 4, 1, 2, 0, 2, 1, 3, 0});
  return seen;
}

// ---- header and times ----

TEST(TextLogVersions, HeaderOfEachVersion) {
  EXPECT_EQ(log_file_header(kV0), "## Player version 1.5 \n## File version 0.0.0 \n");
  EXPECT_EQ(log_file_header(kV2), "## Player version 1.6.5 \n## File version 0.2.0 \n");
}

TEST(TextLogVersions, TimesHaveSixDecimalsByDefaultAndThreeOnRequest) {
  EXPECT_EQ(format_sync_line(Timestamp{1086000000, 250001}, "h", 6665),
            "1086000000.250001 h 6665 sync 00 1086000000.250001 \n");
  EXPECT_EQ(format_sync_line(12.5, "h", 6665), "0000000012.500000 h 6665 sync 00 0000000012.500000 \n");
  EXPECT_EQ(format_sync_line(Timestamp{12, 500400}, "h", 6665, {.time_decimals = 3}),
            "0000000012.500 h 6665 sync 00 0000000012.500 \n");
  EXPECT_THROW(format_sync_line(1.0, "h", 6665, {.time_decimals = 4}), std::invalid_argument);
}

TEST(TextLogVersions, ThreeAndSixDecimalTimesReadBack) {
  const auto three = std::get<SyncLine>(parse_log_line("1086000000.250 h 6665 sync 00 1086000000.250 ", "f", 1));
  EXPECT_EQ(three.server_time, (Timestamp{1086000000, 250000}));
  const auto six = std::get<SyncLine>(parse_log_line("1086000000.250001 h 6665 sync 00 0000000001.000009 ", "f", 1));
  EXPECT_EQ(six.server_time, (Timestamp{1086000000, 250001}));
  EXPECT_EQ(six.data_time, (Timestamp{1, 9}));
}

// ---- 0.2.0 golden lines (spec §6) ----

TEST(TextLogVersions, Laser020WritesTheResolutionWithEightDecimals) {
  const auto line = line_of(kLaserCode, sample_laser(), kV2);
  EXPECT_EQ(line, prefix("laser") + "-1.5708 +1.5708 +0.00436332 0002 1.000  5 2.500  0 \n");
  EXPECT_EQ(decode<LaserData>(read_back(line, LogFormatVersion::k0_2_0).message.payload), sample_laser());
}

TEST(TextLogVersions, Truth020IsA3dPose) {
  const auto line = line_of(kTruthCode, sample_truth(), kV2);
  EXPECT_EQ(line, prefix("truth") + "+01.500 -00.250 +00.000 +0.000 +0.000 +1.571\n");
  EXPECT_EQ(decode<TruthData>(read_back(line, LogFormatVersion::k0_2_0).message.payload), sample_truth());
}

TEST(TextLogVersions, Fiducial020IsA3dPoseWithSixUncertainties) {
  const auto line = line_of(kFiducialCode, sample_fiducial(), kV2);
  EXPECT_EQ(line, prefix("fiducial") +
                      "1 7 +0.0000 +2.0000 +0.0000 +0.000 +0.000 -1.571 +00.100 +0.035 +00.000 +0.000 +0.000 +0.000\n");
  // Range, bearing, orientation and the uncertainties all come back.
  EXPECT_EQ(decode<FiducialData>(read_back(line, LogFormatVersion::k0_2_0).message.payload), sample_fiducial());
}

TEST(TextLogVersions, Gps020HasVdopAfterHdop) {
  const auto line = line_of(kGpsCode, sample_gps(), kV2);
  EXPECT_EQ(line, prefix("gps") +
                      "1086001086.000 34.052199 -118.243699 71.500000 385321.000 3768800.500 "
                      "1.200 0.000 2.500 4.000 1 7\n");
  EXPECT_EQ(decode<GpsData>(read_back(line, LogFormatVersion::k0_2_0).message.payload), sample_gps());
}

TEST(TextLogVersions, A020LineIsAnErrorWhenReadAs000) {
  const auto line = line_of(kTruthCode, sample_truth(), kV2);
  EXPECT_THROW(parse_log_line(line, "f", 1), LogParseError);
}

// ---- extension interfaces: golden lines ----

TEST(TextLogExtensions, GoldenLines) {
  EXPECT_EQ(line_of(kWifiCode, sample_wifi(), kV0), prefix("wifi") + "192.168.0.1 40 200 150 - 1 2 3\n");
  EXPECT_EQ(line_of(kSonarCode, sample_sonar(), kV0), prefix("sonar") + "3 1.000 0.250 65.535\n");
  EXPECT_EQ(line_of(kIrCode, sample_ir(), kV0), prefix("ir") + "2 0.120 512 3.000 7\n");
  EXPECT_EQ(line_of(kPowerCode, PowerData{127}, kV0), prefix("power") + "12.7\n");
  EXPECT_EQ(line_of(kBumperCode, sample_bumper(), kV0), prefix("bumper") + "3 0 1 0\n");
  EXPECT_EQ(line_of(kPtzCode, PtzData{90, -30, 60, 10, -5}, kV0),
            prefix("ptz") + "+1.5708 -0.5236 +1.0472 +0.1745 -0.0873\n");
  EXPECT_EQ(line_of(kLocalizeCode, sample_localize(false), kV0),
            prefix("localize") + "2 1086000000.000005 1 +1.500 -2.000 +0.0174533 0 0 0 0 0 0 0 0 0 0.500000\n");
  EXPECT_EQ(line_of(kBlobfinderCode, sample_blobfinder(), kV0),
            prefix("blobfinder") + "320 240 2 0 16711680 100 10 20 5 15 15 25 1.500 2 255 4 1 2 0 2 1 3 0.000\n");
}

TEST(TextLogExtensions, WifiKeepsOnlyItsLinks) {
  // The groups 1.5's readlog parsed; the rest of the struct has no field.
  auto wifi = sample_wifi();
  wifi.throughput = 5;
  wifi.mode = kWifiModeInfra;
  wifi.ap = "00:11:22:33:44:55";
  const auto back = decode<WifiData>(read_back(line_of(kWifiCode, wifi, kV0), LogFormatVersion::k0_0_0).message.payload);
  EXPECT_EQ(back, sample_wifi());
}

TEST(TextLogExtensions, WhatTheFormatCannotHoldIsRefused) {
  WifiData wifi;
  wifi.link_count = 1;
  wifi.links[0].ip = "a b";
  EXPECT_THROW(line_of(kWifiCode, wifi, kV0), std::invalid_argument);
  auto seen = sample_blobfinder();
  seen.header[5] = {1, 9};  // past the two blobs
  EXPECT_THROW(line_of(kBlobfinderCode, seen, kV0), std::invalid_argument);
}

TEST(TextLogExtensions, MalformedExtensionLines) {
  const std::string at = "1.000 h 6665 ";
  auto error_of = [](const std::string& text) {
    try {
      parse_log_line(text, "x.log", 4);
    } catch (const LogParseError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of(at + "sonar 00 1.000 2 1.000"), "x.log:4:36: line ends after 1 of its 2 ranges");
  EXPECT_EQ(error_of(at + "wifi 00 1.000 10.0.0.1 1 2"),
            "x.log:4:40: wifi fields come in groups of 4 (ip qual level noise); the last group has 3");
  EXPECT_EQ(error_of(at + "power 00 1.000 12.7 1"), "x.log:4:34: unexpected field '1' after volts");
  EXPECT_EQ(error_of(at + "blobfinder 00 1.000 1 1 2 3 0 0 0 0 0 0 0 0 0.0 1 0 0 0 0 0 0 0 0 0.0"),
            "x.log:4:62: blobs must come grouped by channel in ascending order; channel 1 follows channel 3");
}

// ---- round trips: every interface, both versions ----

struct Case {
  std::uint16_t interface;
  std::vector<std::uint8_t> payload;
  // What the file keeps of it: the payload after a trip through the log.
  std::vector<std::uint8_t> kept;
};

std::vector<Case> cases(LogFormatVersion version) {
  PositionData position{1234, -567, 359, 300, -20, -45, 1};
  // 0.0.0 drops the fiducial uncertainties; 0.2.0 keeps them.
  FiducialData fiducial_kept = sample_fiducial();
  if (version == LogFormatVersion::k0_0_0) fiducial_kept.fiducials[0].upose = {0, 0, 0};
  // Laser: ranges come back in mm with range_res 1.
  LaserData laser = sample_laser();
  laser.range_res = 10;
  laser.ranges = {100, 250};
  // Position3d: angles of whole degrees come back within 10 arc-seconds; these
  // (multiples of 1/10000 rad) come back exactly.
  Position3dData position3d{1000, -2500, 7, 2063, -4125, 20626, 100, 0, -50, 206, -413, 0, 1};
  return {
      {kLaserCode, encode(laser), encode(sample_laser())},
      {kPositionCode, encode(position), encode(position)},
      {kPosition3dCode, encode(position3d), encode(position3d)},
      {kGpsCode, encode(sample_gps()), encode(sample_gps())},
      {kTruthCode, encode(sample_truth()), encode(sample_truth())},
      {kFiducialCode, encode(sample_fiducial()), encode(fiducial_kept)},
      {kWifiCode, encode(sample_wifi()), encode(sample_wifi())},
      {kSonarCode, encode(sample_sonar()), encode(sample_sonar())},
      {kIrCode, encode(sample_ir()), encode(sample_ir())},
      {kPowerCode, encode(PowerData{127}), encode(PowerData{127})},
      {kBumperCode, encode(sample_bumper()), encode(sample_bumper())},
      {kLocalizeCode, encode(sample_localize(true)), encode(sample_localize(true))},
      {kPtzCode, encode(PtzData{90, -30, 60, 10, -5}), encode(PtzData{90, -30, 60, 10, -5})},
      {kBlobfinderCode, encode(sample_blobfinder()), encode(sample_blobfinder())},
  };
}

void round_trip_every_interface(const TextLogWriterOptions& options) {
  for (const auto& c : cases(options.version)) {
    const auto message = data_message(c.interface, 3, c.payload, {1086000000, 123457}, {1086000000, 9});
    const auto line = format_data_line(message, "robot1", 6665, options);
    SCOPED_TRACE(line);
    const auto back = read_back(line, options.version);
    EXPECT_EQ(back.device, (DeviceAddress{c.interface, 3}));
    EXPECT_EQ(back.message.time(), (Timestamp{1086000000, 123457}));
    EXPECT_EQ(back.message.timestamp(), (Timestamp{1086000000, 9}));
    EXPECT_EQ(back.message.payload, c.kept);
    // And what came back writes the same line again.
    EXPECT_EQ(format_data_line(back.message, back.host, back.port, options), line);
  }
}

TEST(TextLogRoundTrips, EveryInterfaceIn000) { round_trip_every_interface(kV0); }
TEST(TextLogRoundTrips, EveryInterfaceIn020) { round_trip_every_interface(kV2); }

TEST(TextLogRoundTrips, AWholeFileInEachVersionThroughTheReader) {
  for (const auto& options : {kV0, kV2}) {
    std::string text = log_file_header(options);
    const auto all = cases(options.version);
    for (const auto& c : all) text += format_data_line(data_message(c.interface, 0, c.payload), "h", 6665, options);
    text += format_sync_line(Timestamp{1086000001, 1}, "h", 6665, options);
    std::istringstream in(text);
    TextLogReader reader(in, "whole.log", {.strict = true});
    for (const auto& c : all) {
      auto line = reader.next();
      ASSERT_TRUE(line.has_value());
      EXPECT_EQ(std::get<DataLine>(*line).message.payload, c.kept) << std::get<DataLine>(*line).interface_name;
    }
    auto sync = reader.next();
    ASSERT_TRUE(sync.has_value());
    EXPECT_EQ(std::get<SyncLine>(*sync).server_time, (Timestamp{1086000001, 1}));
    EXPECT_FALSE(reader.next().has_value());
    EXPECT_EQ(reader.format_version(), options.version);
  }
}

}  // namespace text_log_version_test
}  // namespace playerkit::log
