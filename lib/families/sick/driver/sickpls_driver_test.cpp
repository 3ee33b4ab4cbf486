// sickpls against an emulated PLS on a pty: found at 38400 or (as it powers
// up) 9600 and moved to `rate`, its centimetres reported in the unit
// range_res says, 1 deg by taking every second value, subranges, requests,
// a silent start and a vanishing laser.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "families/sick/driver/sick_driver_test_support.hpp"

namespace playerkit::drivers {
namespace sickpls_driver_test {

using namespace sick_driver_test_support;
using emulators::SickLaserEmulator;
using protocol::MessageType;

RigOptions pls(int power_up_baud = 38400) {
  RigOptions options;
  options.model = Model::pls;
  options.power_up_baud = power_up_baud;
  return options;
}

// Beams off the hand-computed walls by more than a centimetre (the PLS's
// step) plus one unit of rounding.
int beams_off_the_walls(const protocol::LaserData& scan) {
  const double metres_per_unit = scan.range_res * 0.001;
  const double tolerance = std::max(1.0, 0.01 / metres_per_unit) + 1.0;
  int wrong = 0;
  for (std::size_t i = 0; i < scan.range_count; ++i) {
    const double expected = room_range(kLaserPose.yaw + beam_angle(scan, i)) / metres_per_unit;
    if (std::abs(scan.ranges[i] - expected) > tolerance) ++wrong;
  }
  return wrong;
}

TEST(Sickpls, AtEveryRateThePlsIsRunAtThatSpeedAndScansTheRoomInMillimetres) {
  for (const int rate : {9600, 38400, 500000}) {
    SCOPED_TRACE(rate);
    LaserRig rig(pls());
    rig.load("rate " + std::to_string(rate));
    ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
    const auto scan = rig.next_scan();
    ASSERT_TRUE(scan) << rig.all_log();
    EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().line_baud(); }), rate);
    EXPECT_EQ(scan->range_count, 361);
    EXPECT_EQ(scan->min_angle, -9000);
    EXPECT_EQ(scan->max_angle, 9000);
    EXPECT_EQ(scan->resolution, 50);
    EXPECT_EQ(scan->range_res, 1);  // millimetres, as range_res says (1.5 sent cm under range_res 1)
    EXPECT_EQ(beams_off_the_walls(*scan), 0);
    EXPECT_EQ(scan->intensity[180], 0);
    EXPECT_NE(rig.logged({"SICK PLS on " + rig.port()}), "") << rig.all_log();
  }
}

TEST(Sickpls, APlsPoweredUpAt9600IsFoundThereAndMovedToTheRate) {
  LaserRig rig(pls(9600));
  rig.load("rate 38400", "retry_interval 0.2");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan()) << rig.all_log();
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().line_baud(); }), 38400);
  EXPECT_GT(rig.with_laser([](RefusingLaser& l) { return l.inner().noise_bytes(); }), 0u);
}

TEST(Sickpls, TheFirstTelegramIsTheSheetsPlsInstallationMode) {
  std::mutex mutex;  // before the rig: its shutdown still traces
  std::vector<std::uint8_t> out;
  LaserRig rig(pls());
  rig.load("rate 38400");
  rig.driver().set_byte_trace([&](bool outgoing, std::span<const std::uint8_t> bytes, auto) {
    std::lock_guard lock(mutex);
    if (outgoing) out.insert(out.end(), bytes.begin(), bytes.end());
  });
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  std::lock_guard lock(mutex);
  const std::vector<std::uint8_t> t1 = {0x02, 0x00, 0x0A, 0x00, 0x20, 0x00, 0x53, 0x49,
                                        0x43, 0x4B, 0x5F, 0x50, 0x4C, 0x53, 0xCC, 0xFC};
  ASSERT_GE(out.size(), t1.size());
  EXPECT_TRUE(std::equal(t1.begin(), t1.end(), out.begin()));
}

TEST(Sickpls, RangeResAndOneDegreeResolutionAreTheDriversWork) {
  LaserRig rig(pls());
  rig.load("rate 500000 range_res 10 resolution 100");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  const auto scan = rig.next_scan();
  ASSERT_TRUE(scan) << rig.all_log();
  EXPECT_EQ(scan->range_count, 181);
  EXPECT_EQ(scan->resolution, 100);
  EXPECT_EQ(scan->range_res, 10);
  EXPECT_EQ(beams_off_the_walls(*scan), 0);
  // The PLS itself still streams its 361 values at 0.5 deg.
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().mode(); }),
            SickLaserEmulator::Mode::streaming_all);
}

TEST(Sickpls, ASubrangeIsStreamedForNarrowerAngles) {
  LaserRig rig(pls());
  rig.load("rate 500000 min_angle 0 max_angle 45");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  const auto scan = rig.next_scan();
  ASSERT_TRUE(scan) << rig.all_log();
  EXPECT_EQ(scan->range_count, 91);
  EXPECT_EQ(scan->min_angle, 0);
  EXPECT_EQ(scan->max_angle, 4500);
  EXPECT_EQ(beams_off_the_walls(*scan), 0);
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().mode(); }),
            SickLaserEmulator::Mode::streaming_subrange);
}

TEST(Sickpls, RequestsAreThoseOfTheLms200WithoutIntensity) {
  LaserRig rig(pls());
  rig.load("rate 500000 pose [0 0.25 -90]");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan());

  auto reply = rig.request({protocol::kLaserGetGeom});
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->type, MessageType::kAck);
  const auto geom = protocol::decode<protocol::LaserGeom>(reply->payload);
  EXPECT_EQ(geom.pose, (std::array<std::int16_t, 3>{0, 250, -90}));
  EXPECT_EQ(geom.size, (std::array<std::int16_t, 2>{150, 150}));

  reply = rig.request({protocol::kLaserGetConfig});
  ASSERT_TRUE(reply);
  EXPECT_EQ(protocol::decode<protocol::LaserConfig>(reply->payload),
            (protocol::LaserConfig{protocol::kLaserGetConfig, -9000, 9000, 50, 1, 0}));

  // Intensity cannot be had from a PLS: the reply says so.
  reply = rig.request(config_request(-4500, 4500, 100, 10, 1));
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->type, MessageType::kAck) << rig.all_log();
  EXPECT_EQ(protocol::decode<protocol::LaserConfig>(reply->payload),
            (protocol::LaserConfig{protocol::kLaserSetConfig, -4500, 4500, 100, 10, 0}));
  std::optional<protocol::LaserData> scan;
  for (int i = 0; i < 20 && (!scan || scan->resolution != 100); ++i) scan = rig.next_scan();
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->resolution, 100);
  EXPECT_EQ(scan->range_count, 91);
  EXPECT_EQ(beams_off_the_walls(*scan), 0);

  reply = rig.request(config_request(-5000, 5000, 25, 1, 0));
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->type, MessageType::kNack);
  EXPECT_NE(rig.logged({"SET_CONFIG refused: resolution 25 is not 50 or 100"}), "") << rig.all_log();
}

TEST(Sickpls, ASilentPlsRefusesTheSubscriptionNamingThePort) {
  RigOptions options = pls();
  emulators::add_fault(options.faults, "silent-start=60");
  LaserRig rig(options);
  rig.load("", "reply_timeout 0.1");
  EXPECT_FALSE(rig.laser().subscribe());
  EXPECT_NE(rig.logged({"setup failed", rig.port() + ": no answer from the SICK PLS at 38400, 9600 baud"}), "")
      << rig.all_log();
}

TEST(Sickpls, APlsThatVanishesIsLostThenFoundAgain) {
  RigOptions options = pls();
  emulators::add_fault(options.faults, "vanish=1.5:2");
  LaserRig rig(options);
  rig.load("rate 38400");
  ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
  ASSERT_TRUE(rig.next_scan());
  ASSERT_TRUE(drivers::testing::eventually([&] { return !rig.laser().available(); }, 10s)) << rig.all_log();
  EXPECT_NE(rig.logged({"lost the SICK PLS on " + rig.port()}), "") << rig.all_log();
  ASSERT_TRUE(drivers::testing::eventually([&] { return rig.laser().available(); }, 15s)) << rig.all_log();
  const auto scan = rig.next_scan();
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->range_count, 361);
}

}  // namespace sickpls_driver_test
}  // namespace playerkit::drivers
