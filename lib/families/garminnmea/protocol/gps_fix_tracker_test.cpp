// Fixes from sentences in any order: the sheet's worked example, a GGA
// before its RMC (no lag), GLL's own fix, midnight, no fix; and the two real
// Garmin logs against what gpsd decodes from them.

#include "families/garminnmea/protocol/gps_fix_tracker.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "families/garminnmea/protocol/gpsd_check_test_support.hpp"
#include "framing/nmea_format.hpp"

namespace playerkit::hardware::garminnmea {
namespace gps_fix_tracker_test {

using namespace gpsd_check_test_support;

std::vector<GpsFix> fixes_of(GpsFixTracker& tracker, const std::vector<std::string>& bodies) {
  std::vector<GpsFix> fixes;
  for (const auto& body : bodies) {
    if (auto fix = tracker.take(body)) fixes.push_back(*fix);
  }
  return fixes;
}

TEST(GpsFixTracker, TheSheetsWorkedExample) {
  GpsFixTracker tracker;
  const auto fixes = fixes_of(tracker, {"GPRMC,123519,A,3401.2345,N,11817.1234,W,000.0,360.0,150604,013.2,E",
                                        "PGRME,15.0,M,22.5,M,27.0,M",
                                        "GPGGA,123519,3401.2345,N,11817.1234,W,1,08,0.9,545.4,M,-33.9,M,,"});
  ASSERT_EQ(fixes.size(), 2u);  // RMC's and GGA's: no filter drops the first fixes
  const GpsFix& fix = fixes.back();
  EXPECT_EQ(fix.time_sec, 1087302919);  // 2004-06-15 12:35:19 UTC
  EXPECT_EQ(wire_angle(fix.latitude), 7348444);
  EXPECT_EQ(wire_angle(fix.longitude), -25549644);
  EXPECT_DOUBLE_EQ(fix.altitude, 545.4);
  EXPECT_EQ(fix.quality, 1);
  EXPECT_EQ(fix.satellites, 8);
  EXPECT_DOUBLE_EQ(fix.hdop, 0.9);
  EXPECT_DOUBLE_EQ(fix.horizontal_error, 15.0);
  EXPECT_DOUBLE_EQ(fix.vertical_error, 22.5);
}

TEST(GpsFixTracker, AGgaBeforeItsRmcHasItsOwnPositionAndDate) {
  GpsFixTracker tracker;
  fixes_of(tracker, {"GPRMC,235959,A,3401.0000,N,11817.0000,W,0,0,311299,,"});
  const auto fixes = fixes_of(tracker, {"GPGGA,000001.50,3402.0000,N,11818.0000,W,2,07,1.1,10.0,M,,M,,",
                                        "GPRMC,000001.50,A,3402.0000,N,11818.0000,W,0,0,010100,,"});
  ASSERT_EQ(fixes.size(), 2u);
  // Across midnight from the last RMC's date: 2000-01-01 00:00:01.5.
  EXPECT_EQ(fixes[0].time_sec, 946684801);
  EXPECT_EQ(fixes[0].time_usec, 500000u);
  EXPECT_NEAR(fixes[0].latitude, 34 + 2 / 60.0, 1e-12);
  EXPECT_EQ(fixes[0].quality, 2);
  EXPECT_EQ(fixes[1].time_sec, 946684801);
  EXPECT_EQ(fixes[1].quality, 2);  // the cycle's GGA's
}

TEST(GpsFixTracker, GllAloneIsAFixAndKeepsTheLastAltitude) {
  GpsFixTracker tracker;
  fixes_of(tracker, {"GPGGA,225308,4527.458,S,16709.165,E,1,05,2.1,14.7,M,1.1,M,,"});
  const auto fixes = fixes_of(tracker, {"GPGLL,4527.459,S,16709.166,E,225309,A"});
  ASSERT_EQ(fixes.size(), 1u);
  EXPECT_EQ(fixes[0].time_sec % 86400, 22 * 3600 + 53 * 60 + 9);
  EXPECT_FALSE(fixes[0].has_date);
  EXPECT_NEAR(fixes[0].latitude, -(45 + 27.459 / 60), 1e-12);
  EXPECT_DOUBLE_EQ(fixes[0].altitude, 14.7);
  EXPECT_EQ(fixes[0].quality, 1);
}

TEST(GpsFixTracker, NoFixIsSaidOnceWithoutAPositionAndNeverInvented) {
  GpsFixTracker tracker;
  const auto fixes = fixes_of(tracker, {"GPRMC,123519,V,,,,,,,150604,,", "GPGGA,123519,,,,,0,00,,,M,,M,,",
                                        "GPGLL,,,,,123519,V", "GPGLL,3401.2345,N,11817.1234,W,123520,V",
                                        "GPGSA,A,1,,,,,,,,,,,,,,,", "PGRMZ,125,f,1"});
  ASSERT_EQ(fixes.size(), 1u);
  EXPECT_FALSE(fixes[0].has_position);
  EXPECT_EQ(fixes[0].quality, 0);
  EXPECT_EQ(fixes[0].latitude, 0);
  EXPECT_EQ(fixes[0].time_sec, 1087302919);
  EXPECT_EQ(tracker.sentences_used(), 6u);
}

TEST(GpsFixTracker, PgrmzAltitudeOnlyFromReceiversWithoutGgaAltitude) {
  GpsFixTracker tracker;
  fixes_of(tracker, {"PGRMZ,125,f,3"});
  auto fixes = fixes_of(tracker, {"GPGLL,3348.452,N,11821.142,W,142214,A"});
  EXPECT_NEAR(fixes.at(0).altitude, 38.1, 1e-9);
  fixes_of(tracker, {"GPGGA,142216,3348.452,N,11821.143,W,1,05,1.8,38.4,M,-32.4,M,,", "PGRMZ,123,f,3"});
  fixes = fixes_of(tracker, {"GPGLL,3348.452,N,11821.143,W,142216,A"});
  EXPECT_DOUBLE_EQ(fixes.at(0).altitude, 38.4);
}

// Every fix gpsd reports is reported: with a time, the last of ours at that
// time of day has gpsd's position (to the wire's 1/60 arc-second) and
// altitude (1 cm); without one (no date yet), ours has its position.
void expect_gpsd_fixes(const std::vector<GpsFix>& ours, const std::string& log) {
  const auto expected = gpsd_fixes(log);
  ASSERT_GE(expected.size(), 7u);
  for (const GpsdFix& theirs : expected) {
    const GpsFix* match = nullptr;
    for (const GpsFix& fix : ours) {
      if (!fix.has_position) continue;
      if (theirs.time_of_day ? fix.time_sec % 86400 == *theirs.time_of_day
                             : wire_angle(fix.latitude) == wire_angle(theirs.latitude) &&
                                   wire_angle(fix.longitude) == wire_angle(theirs.longitude)) {
        match = &fix;
      }
    }
    ASSERT_TRUE(match) << log << ": no fix at " << theirs.time_of_day.value_or(-1);
    EXPECT_LE(std::abs(wire_angle(match->latitude) - wire_angle(theirs.latitude)), 1) << theirs.time_of_day.value_or(-1);
    EXPECT_LE(std::abs(wire_angle(match->longitude) - wire_angle(theirs.longitude)), 1);
    if (theirs.altitude && theirs.time_of_day) EXPECT_NEAR(match->altitude, *theirs.altitude, 0.01);
    EXPECT_EQ(match->quality, 1);  // every GGA of both logs says 1
  }
}

std::vector<GpsFix> decode(const std::string& log) {
  GpsFixTracker tracker;
  std::vector<std::string> bodies;
  for (const auto& line : log_sentences(log)) {
    const auto bytes = std::vector<std::uint8_t>(line.begin(), line.end());
    bodies.emplace_back(framing::nmea_body(bytes));
  }
  return fixes_of(tracker, bodies);
}

TEST(GpsFixTracker, Garmin48AsGpsdDecodesIt) { expect_gpsd_fixes(decode("garmin48.log"), "garmin48.log"); }
TEST(GpsFixTracker, Garmin38AsGpsdDecodesIt) { expect_gpsd_fixes(decode("garmin38.log"), "garmin38.log"); }

}  // namespace gps_fix_tracker_test
}  // namespace playerkit::hardware::garminnmea
