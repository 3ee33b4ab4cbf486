#include "client/typed/laser.hpp"

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/si_units.hpp"

namespace playerkit::client {
namespace laser_test {

constexpr double kHalfPi = 1.5707963267948966;
constexpr double kHalfDegree = 0.008726646259971648;

protocol::LaserData three_beams(std::uint16_t range_res) {
  protocol::LaserData d;
  d.min_angle = -9000;
  d.max_angle = -8900;
  d.resolution = 50;
  d.range_res = range_res;
  d.range_count = 3;
  d.ranges[0] = 1500;
  d.ranges[1] = 0;
  d.ranges[2] = 8191;
  d.intensity[0] = 0;
  d.intensity[1] = 1;
  d.intensity[2] = 7;
  d.ranges[3] = 999;  // beyond range_count: not part of the scan
  return d;
}

TEST(TypedLaser, ScanGolden) {
  const LaserScan scan = to_si(three_beams(1));
  EXPECT_DOUBLE_EQ(scan.min_angle, -kHalfPi);
  EXPECT_DOUBLE_EQ(scan.max_angle, -1.5533430342749535);  // -89 degrees
  EXPECT_DOUBLE_EQ(scan.resolution, kHalfDegree);
  ASSERT_EQ(scan.ranges.size(), 3u);
  EXPECT_DOUBLE_EQ(scan.ranges[0], 1.5);
  EXPECT_DOUBLE_EQ(scan.ranges[1], 0.0);
  EXPECT_DOUBLE_EQ(scan.ranges[2], 8.191);
  ASSERT_EQ(scan.bearings.size(), 3u);
  EXPECT_DOUBLE_EQ(scan.bearings[0], -kHalfPi);
  EXPECT_DOUBLE_EQ(scan.bearings[1], -1.562069680534925);  // -89.5 degrees
  EXPECT_DOUBLE_EQ(scan.bearings[2], -1.5533430342749535);
  EXPECT_EQ(scan.intensities, (std::vector<std::uint8_t>{0, 1, 7}));
}

TEST(TypedLaser, RangeResolutionMultipliesRanges) {
  EXPECT_DOUBLE_EQ(to_si(three_beams(10)).ranges[0], 15.0);
  EXPECT_DOUBLE_EQ(to_si(three_beams(100)).ranges[2], 819.1);
  EXPECT_DOUBLE_EQ(to_si(three_beams(0)).ranges[0], 1.5);  // unset: millimetres
}

TEST(TypedLaser, BearingsDoNotDriftOverAFullScan) {
  protocol::LaserData d;
  d.min_angle = -9000;
  d.max_angle = 9000;
  d.resolution = 50;
  d.range_res = 1;
  d.range_count = 361;
  const LaserScan scan = to_si(d);
  ASSERT_EQ(scan.bearings.size(), 361u);
  EXPECT_DOUBLE_EQ(scan.bearings[180], 0.0);
  EXPECT_DOUBLE_EQ(scan.bearings[360], kHalfPi);
}

TEST(TypedLaser, AgreesWithTheSiJsonOfTheSamePayload) {
  const auto bytes = protocol::encode(three_beams(10));
  const auto json = protocol::payload_to_si_json(protocol::kLaserCode, protocol::MessageType::kData, bytes);
  const LaserScan scan = to_si(protocol::decode<protocol::LaserData>(bytes));
  EXPECT_EQ(json["min_angle"].get<double>(), scan.min_angle);
  EXPECT_EQ(json["resolution"].get<double>(), scan.resolution);
  EXPECT_EQ(json["ranges"].get<std::vector<double>>(), scan.ranges);
}

TEST(TypedLaser, GeometryAndConfigGolden) {
  protocol::LaserGeom geom;
  geom.pose = {120, -30, 180};
  geom.size = {155, 185};
  const LaserGeometry g = to_si(geom);
  EXPECT_DOUBLE_EQ(g.pose.x, 0.12);
  EXPECT_DOUBLE_EQ(g.pose.y, -0.03);
  EXPECT_DOUBLE_EQ(g.pose.yaw, 3.141592653589793);
  EXPECT_DOUBLE_EQ(g.length, 0.155);
  EXPECT_DOUBLE_EQ(g.width, 0.185);

  protocol::LaserConfig wire;
  wire.subtype = protocol::kLaserGetConfig;
  wire.min_angle = -9000;
  wire.max_angle = 9000;
  wire.resolution = 25;
  wire.range_res = 10;
  wire.intensity = 1;
  const LaserConfig c = to_si(wire);
  EXPECT_DOUBLE_EQ(c.min_angle, -kHalfPi);
  EXPECT_DOUBLE_EQ(c.resolution, 0.004363323129985824);
  EXPECT_EQ(c.range_res, 10);
  EXPECT_TRUE(c.intensity);
}

TEST(TypedLaser, SetConfigRoundsToHundredthsOfADegree) {
  const LaserConfig c{-kHalfPi, kHalfPi, kHalfDegree, 1, true};
  const protocol::LaserConfig wire = set_config_request(c);
  EXPECT_EQ(wire.subtype, protocol::kLaserSetConfig);
  EXPECT_EQ(wire.min_angle, -9000);
  EXPECT_EQ(wire.max_angle, 9000);
  EXPECT_EQ(wire.resolution, 50);
  EXPECT_EQ(wire.range_res, 1);
  EXPECT_EQ(wire.intensity, 1);
  // 0.004 degree above 90 rounds back to 90; far outside int16 clamps.
  EXPECT_EQ(set_config_request({-kHalfPi, kHalfPi + 7e-5, kHalfDegree, 1, false}).max_angle, 9000);
  EXPECT_EQ(set_config_request({-1000.0, 1000.0, -1.0, 1, false}).min_angle, -32768);
  EXPECT_EQ(set_config_request({-1000.0, 1000.0, -1.0, 1, false}).max_angle, 32767);
  EXPECT_EQ(set_config_request({-1000.0, 1000.0, -1.0, 1, false}).resolution, 0);
  EXPECT_THROW(set_config_request({std::nan(""), 0, 0, 1, false}), std::invalid_argument);
}

}  // namespace laser_test
}  // namespace playerkit::client
