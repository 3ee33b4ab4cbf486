// sicklms200's requests against an emulated LMS 200 on a pty: GET_GEOM,
// GET_CONFIG, SET_CONFIG reconfiguring the laser (and NACKed when the
// combination is impossible or the laser refuses), everything else NACK.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "families/sick/driver/sick_driver_test_support.hpp"

namespace playerkit::drivers {
namespace sicklms200_requests_test {

using namespace sick_driver_test_support;
using emulators::SickLaserEmulator;
using protocol::MessageType;

// The first scan published with `resolution` (scans already on their way
// when the laser was reconfigured may come first), within a few.
std::optional<protocol::LaserData> scan_at(LaserRig& rig, int resolution) {
  for (int i = 0; i < 20; ++i) {
    auto scan = rig.next_scan();
    if (!scan) return std::nullopt;
    if (scan->resolution == resolution) return scan;
  }
  return std::nullopt;
}

struct Sicklms200Requests : ::testing::Test {
  void SetUp() override {
    rig.load("rate 500000 pose [0.1 -0.2 90] size [0.2 0.3]");
    ASSERT_TRUE(rig.laser().subscribe()) << rig.all_log();
    ASSERT_TRUE(rig.next_scan()) << rig.all_log();
  }
  protocol::LaserConfig config_now() {
    const auto reply = rig.request({protocol::kLaserGetConfig});
    if (!reply || reply->type != MessageType::kAck) throw std::runtime_error("GET_CONFIG not acknowledged");
    return protocol::decode<protocol::LaserConfig>(reply->payload);
  }
  LaserRig rig;
};

TEST_F(Sicklms200Requests, GetGeomGivesThePoseAndSizeOfTheOptions) {
  const auto reply = rig.request({protocol::kLaserGetGeom});
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->type, MessageType::kAck);
  ASSERT_EQ(reply->payload.size(), protocol::LaserGeom::kWireSize);
  const auto geom = protocol::decode<protocol::LaserGeom>(reply->payload);
  EXPECT_EQ(geom.subtype, protocol::kLaserGetGeom);
  EXPECT_EQ(geom.pose, (std::array<std::int16_t, 3>{100, -200, 90}));
  EXPECT_EQ(geom.size, (std::array<std::int16_t, 2>{200, 300}));
}

TEST_F(Sicklms200Requests, GetConfigGivesTheScanInForce) {
  const auto reply = rig.request({protocol::kLaserGetConfig});
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->type, MessageType::kAck);
  ASSERT_EQ(reply->payload.size(), protocol::LaserConfig::kWireSize);
  EXPECT_EQ(protocol::decode<protocol::LaserConfig>(reply->payload),
            (protocol::LaserConfig{protocol::kLaserGetConfig, -9000, 9000, 50, 1, 1}));
}

TEST_F(Sicklms200Requests, SetConfigReconfiguresTheLaserAndTheScansThatFollow) {
  const auto reply = rig.request(config_request(-4500, 4500, 100, 10, 0));
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->type, MessageType::kAck) << rig.all_log();
  EXPECT_EQ(protocol::decode<protocol::LaserConfig>(reply->payload),
            (protocol::LaserConfig{protocol::kLaserSetConfig, -4500, 4500, 100, 10, 0}));

  // The laser itself: 1 deg variant, centimetres, no reflector bits, a subrange.
  rig.with_laser([](RefusingLaser& l) {
    EXPECT_EQ(l.inner().variant(), (sick::Variant{180, 100}));
    EXPECT_EQ(l.inner().unit(), sick::Unit::centimetre);
    EXPECT_EQ(l.inner().config().measuring_mode(), sick::MeasuringMode::fields_and_dazzle);
    EXPECT_EQ(l.inner().mode(), SickLaserEmulator::Mode::streaming_subrange);
    return 0;
  });
  const auto scan = scan_at(rig, 100);
  ASSERT_TRUE(scan) << rig.all_log();
  EXPECT_EQ(scan->range_count, 91);
  EXPECT_EQ(scan->min_angle, -4500);
  EXPECT_EQ(scan->max_angle, 4500);
  EXPECT_EQ(scan->range_res, 10);
  for (std::size_t i = 0; i < scan->range_count; ++i) {
    ASSERT_NEAR(scan->ranges[i], room_range(beam_angle(*scan, i)) / 0.01, 1.0) << "beam " << i;
    ASSERT_EQ(scan->intensity[i], 0);
  }
  EXPECT_EQ(config_now(), (protocol::LaserConfig{protocol::kLaserGetConfig, -4500, 4500, 100, 10, 0}));
  EXPECT_NE(rig.logged({"now scanning 180 deg at 1 deg, -45..45 deg (91 values), cm, intensity off"}), "")
      << rig.all_log();
}

TEST_F(Sicklms200Requests, SetConfigToQuarterDegreesNarrowsTheFieldOfViewTo100) {
  const auto reply = rig.request(config_request(-9000, 9000, 25, 1, 1));
  ASSERT_TRUE(reply);
  ASSERT_EQ(reply->type, MessageType::kAck) << rig.all_log();
  EXPECT_EQ(protocol::decode<protocol::LaserConfig>(reply->payload),
            (protocol::LaserConfig{protocol::kLaserSetConfig, -5000, 5000, 25, 1, 1}));
  const auto scan = scan_at(rig, 25);
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->range_count, 401);
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().variant(); }), (sick::Variant{100, 25}));
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().mode(); }),
            SickLaserEmulator::Mode::streaming_all);
}

TEST_F(Sicklms200Requests, ImpossibleConfigurationsAreRefusedWithALogLineAndTheScanKept) {
  const std::vector<std::pair<std::vector<std::uint8_t>, std::string>> cases = {
      {config_request(-9000, 9000, 30, 1, 1), "SET_CONFIG refused: resolution 30 is not one of 25, 50, 100"},
      {config_request(-9000, 9000, 50, 7, 1), "SET_CONFIG refused: range_res 7 is not one of 1, 10, 100"},
      {config_request(1000, -1000, 50, 1, 1), "SET_CONFIG refused: min_angle 10 deg is above max_angle -10 deg"},
      {std::vector<std::uint8_t>{protocol::kLaserSetConfig, 0, 0}, "SET_CONFIG refused: 3 bytes"},
  };
  for (const auto& [payload, line] : cases) {
    const auto reply = rig.request(payload);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->type, MessageType::kNack) << line;
    EXPECT_TRUE(reply->payload.empty());
    EXPECT_NE(rig.logged({line}), "") << rig.all_log();
  }
  const auto scan = rig.next_scan();
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->range_count, 361);
  EXPECT_EQ(config_now(), (protocol::LaserConfig{protocol::kLaserGetConfig, -9000, 9000, 50, 1, 1}));
}

TEST_F(Sicklms200Requests, AVariantTheLaserRefusesIsNackedAndThePreviousScanRestored) {
  rig.with_laser([](RefusingLaser& l) {
    l.refuse_next_variant();
    return 0;
  });
  const auto reply = rig.request(config_request(-9000, 9000, 100, 1, 1));
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->type, MessageType::kNack);
  EXPECT_NE(rig.logged({"SET_CONFIG refused", "the laser refused the variant 180 deg at 1.00 deg (BB 00"}), "")
      << rig.all_log();
  // Back where it was: 0.5 deg, all 361 values.
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().variant(); }), (sick::Variant{180, 50}));
  EXPECT_EQ(rig.with_laser([](RefusingLaser& l) { return l.inner().mode(); }),
            SickLaserEmulator::Mode::streaming_all);
  const auto sent = rig.with_laser([](RefusingLaser& l) { return l.inner().scans_sent(); });
  EXPECT_TRUE(drivers::testing::eventually(
      [&] { return rig.with_laser([](RefusingLaser& l) { return l.inner().scans_sent(); }) > sent; }));
  const auto scan = rig.next_scan();
  ASSERT_TRUE(scan);
  EXPECT_EQ(scan->range_count, 361);
  EXPECT_TRUE(rig.laser().available());
}

TEST_F(Sicklms200Requests, EverythingElseIsNacked) {
  const std::vector<std::vector<std::uint8_t>> others = {
      {protocol::kLaserPowerConfig, 1}, {99}, {}, {0}};
  for (const auto& payload : others) {
    const auto reply = rig.request(payload);
    ASSERT_TRUE(reply);
    EXPECT_EQ(reply->type, MessageType::kNack);
  }
  EXPECT_TRUE(rig.next_scan());
}

}  // namespace sicklms200_requests_test
}  // namespace playerkit::drivers
