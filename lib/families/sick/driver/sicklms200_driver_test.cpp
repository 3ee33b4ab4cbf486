// sicklms200 against an emulated LMS 200 on a real pseudo-terminal: setup
// at every speed, every variant, unit and intensity setting, inverted, the
// 9600 fallback, TCP, and what is left on the laser at shutdown. Ranges are
// checked against the room's walls computed by hand.
#include <gtest/gtest.h>

#include <string>

#include "families/sick/driver/sick_driver_test_support.hpp"

namespace playerkit::drivers {
namespace sicklms200_driver_test {

using namespace sick_driver_test_support;
using emulators::SickLaserEmulator;

// Beams whose range is off the hand-computed wall distance by more than
// one unit step (plus the rounding of a dm value made from cm).
std::string beams_off_the_walls(const protocol::LaserData& scan, bool inverted = false) {
  const double metres_per_unit = scan.range_res * 0.001;
  std::string report;
  int wrong = 0;
  for (std::size_t i = 0; i < scan.range_count; ++i) {
    const double angle = beam_angle(scan, i);
    const double expected = room_range(kLaserPose.yaw + (inverted ? -angle : angle)) / metres_per_unit;
    if (std::abs(scan.ranges[i] - expected) > 1.0) {
      if (++wrong <= 3) {
        report += "beam " + std::to_string(i) + ": " + std::to_string(scan.ranges[i]) + " expected " +
                  std::to_string(expected) + "; ";
      }
    }
  }
  return wrong == 0 ? "" : std::to_string(wrong) + " beams off: " + report;
}

TEST(Sicklms200, AtEveryRateTheLaserIsRunAtThatSpeedAndScansTheRoom) {
  for (const int rate : {9600, 38400, 500000}) {
    SCOPED_TRACE(rate);
    LaserRig rig;
    rig.load("rate " + std::to_string(rate));
    ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
    const auto scan = rig.next_scan();
    ASSERT_TRUE(scan) << rig.all_log();
    EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().line_baud(); }), rate);
    EXPECT_EQ(scan->range_count, 361);
    EXPECT_EQ(scan->min_angle, -9000);
    EXPECT_EQ(scan->max_angle, 9000);
    EXPECT_EQ(scan->resolution, 50);
    EXPECT_EQ(scan->range_res, 1);
    EXPECT_EQ(beams_off_the_walls(*scan), "");
    EXPECT_NE(rig.logged({"SICK LMS 200 (LMS200;30106) on " + rig.port(), "at " + std::to_string(rate) + " baud"}),
              "")
        << rig.all_log();
  }
}

TEST(Sicklms200, EveryVariantIsSetOnTheLaserAndReportedAsThe15DriverDid) {
  struct Case {
    int resolution, fov, count;
  };
  for (const Case c : {Case{50, 180, 361}, Case{100, 180, 181}, Case{25, 100, 401}, Case{50, 100, 201},
                       Case{100, 100, 101}}) {
    SCOPED_TRACE(std::to_string(c.resolution) + " at " + std::to_string(c.fov));
    LaserRig rig;
    rig.load("rate 500000 resolution " + std::to_string(c.resolution) + " fov " + std::to_string(c.fov));
    ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
    const auto scan = rig.next_scan();
    ASSERT_TRUE(scan) << rig.all_log();
    const auto variant = rig.with_laser([](RefusingLaser& l) { return l.inner().variant(); });
    EXPECT_EQ(variant.width_deg, c.fov);
    EXPECT_EQ(variant.resolution_cdeg, c.resolution);
    EXPECT_EQ(scan->range_count, c.count);
    EXPECT_EQ(scan->resolution, c.resolution);
    EXPECT_EQ(scan->min_angle, -c.fov * 50);
    EXPECT_EQ(scan->max_angle, c.fov * 50);
    EXPECT_EQ(beams_off_the_walls(*scan), "");
  }
}

TEST(Sicklms200, RangeResChoosesTheLasersUnitAndTheReportedOne) {
  struct Case {
    int range_res;
    sick::Unit unit;
  };
  for (const Case c : {Case{1, sick::Unit::millimetre}, Case{10, sick::Unit::centimetre},
                       Case{100, sick::Unit::centimetre}}) {
    SCOPED_TRACE(c.range_res);
    LaserRig rig;
    rig.load("rate 500000 range_res " + std::to_string(c.range_res));
    ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
    const auto scan = rig.next_scan();
    ASSERT_TRUE(scan) << rig.all_log();
    EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().unit(); }), c.unit);
    EXPECT_EQ(scan->range_res, c.range_res);
    EXPECT_EQ(beams_off_the_walls(*scan), "");
  }
}

TEST(Sicklms200, IntensityReportsTheReflectorLevelOnlyWhenAskedFor) {
  // Tape of level 5 on the east wall where the middle beam (0 deg) hits it.
  const std::vector<emulators::SickReflector> tape = {{{kEast, 1.2}, {kEast, 1.6}, 5}};
  for (const bool intensity : {true, false}) {
    SCOPED_TRACE(intensity);
    LaserRig rig({.reflectors = tape});
    rig.load(std::string("rate 500000 intensity ") + (intensity ? "1" : "0"));
    ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
    const auto scan = rig.next_scan();
    ASSERT_TRUE(scan) << rig.all_log();
    EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().config().measuring_mode(); }),
              intensity ? sick::MeasuringMode::reflector_levels : sick::MeasuringMode::fields_and_dazzle);
    EXPECT_EQ(scan->intensity[180], intensity ? 5 : 0);
    EXPECT_EQ(scan->intensity[360], 0);  // the north wall, no tape
    EXPECT_EQ(beams_off_the_walls(*scan), "");
  }
}

TEST(Sicklms200, AnInvertedLaserReportsItsBeamsMirrored) {
  LaserRig rig;
  rig.load("rate 500000 invert 1 min_angle -90 max_angle 45");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  const auto scan = rig.next_scan();
  ASSERT_TRUE(scan) << rig.all_log();
  EXPECT_EQ(scan->range_count, 271);
  EXPECT_EQ(scan->min_angle, -4500);
  EXPECT_EQ(scan->max_angle, 9000);
  // Each reading is the beam the laser sent at the mirrored angle.
  EXPECT_EQ(beams_off_the_walls(*scan, true), "");
  EXPECT_NE(beams_off_the_walls(*scan, false), "");
}

TEST(Sicklms200, ALaserAt9600IsFoundThereAfterASilentTryAt38400AndMovedUp) {
  LaserRig rig({.power_up_baud = 9600});
  rig.load("", "retry_interval 0.2");  // the default 1 s reply timeout
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan()) << rig.all_log();
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().line_baud(); }), 38400);
  // What it sent at 38400 while the laser listened at 9600 was noise to it.
  EXPECT_GT(rig.with_laser([](RefusingLaser& l) { return l.inner().noise_bytes(); }), 0u);
}

TEST(Sicklms200, OverTcpTheBridgesSpeedIsLeftAlone) {
  LaserRig rig({.tcp = true});
  EXPECT_EQ(rig.port().rfind("tcp:127.0.0.1:", 0), 0u);
  rig.load("rate 500000");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  const auto scan = rig.next_scan();
  ASSERT_TRUE(scan) << rig.all_log();
  EXPECT_EQ(beams_off_the_walls(*scan), "");
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().line_baud(); }), 38400);
}

TEST(Sicklms200, ShutdownStopsTheStreamAndLeavesAFastLaserAt38400) {
  LaserRig rig;
  rig.load("rate 500000");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan());
  rig.laser().unsubscribe();
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().mode(); }),
            SickLaserEmulator::Mode::installation);
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().line_baud(); }), 38400);
  const auto sent = rig.with_laser([](RefusingLaser& l) { return l.inner().scans_sent(); });
  // A second subscription finds it at once and streams again.
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan());
  EXPECT_GT(rig.with_laser([](RefusingLaser& l) { return l.inner().scans_sent(); }), sent);
}

TEST(Sicklms200, ScansAreStampedAndCountedAsTheyArrive) {
  LaserRig rig;
  rig.load("rate 500000");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  const auto before = rig.builtin.clock.now();
  ASSERT_TRUE(rig.next_scan());
  ASSERT_TRUE(rig.next_scan());
  EXPECT_GE(rig.laser().latest_data()->timestamp, before);
  EXPECT_GE(counter(rig.driver(), "scans"), 2u);
  EXPECT_GE(counter(rig.driver(), "telegrams"), 2u);
  EXPECT_GT(counter(rig.driver(), "bytes_in"), 2u * 732u);
  EXPECT_GT(counter(rig.driver(), "bytes_out"), 0u);
  EXPECT_EQ(counter(rig.driver(), "checksum_errors"), 0u);
  // On a clean line the only bytes skipped are the ACK before each reply.
  EXPECT_EQ(counter(rig.driver(), "resyncs"),
            rig.with_laser([](RefusingLaser& l) { return l.inner().requests_answered(); }));
}

}  // namespace sicklms200_driver_test
}  // namespace playerkit::drivers
