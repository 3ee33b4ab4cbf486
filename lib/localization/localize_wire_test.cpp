#include "localization/localize_wire.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "protocol/binary_codec.hpp"

namespace playerkit::localization {
namespace localize_wire_test {

constexpr double kDegree = std::numbers::pi / 180.0;

TEST(LocalizeWire, HypothesisInMillimetresAndArcSeconds) {
  amcl::Hypothesis hypothesis;
  hypothesis.mean = {1.5, -2.0, 90 * kDegree};
  hypothesis.covariance << 0.01, 0.002, 0.001,  //
      0.002, 0.04, 0.0,                         //
      0.001, 0.0, kDegree * kDegree;
  hypothesis.weight = 0.25;
  const protocol::LocalizeHypothesis wire = to_wire(hypothesis);
  EXPECT_EQ(wire.mean, (std::array<std::int32_t, 3>{1500, -2000, 324000}));
  EXPECT_EQ(wire.cov[0][0], 10000);     // (100 mm)^2
  EXPECT_EQ(wire.cov[0][1], 2000);      // mm^2
  EXPECT_EQ(wire.cov[1][1], 40000);
  EXPECT_EQ(wire.cov[2][2], 12960000);  // (3600 arcsec)^2
  EXPECT_EQ(wire.cov[0][2], 206265);    // 0.001 m rad = 1 mm * 206264.8 arcsec
  EXPECT_EQ(wire.cov[2][0], wire.cov[0][2]);
  EXPECT_EQ(wire.alpha, 250000u);

  const Eigen::Matrix3d back = covariance_from_wire(wire.cov);
  EXPECT_TRUE(back.isApprox(hypothesis.covariance, 1e-5));
  const geometry::Pose2 mean = pose_from_wire(wire.mean);
  EXPECT_NEAR(mean.x, 1.5, 1e-9);
  EXPECT_NEAR(mean.yaw, 90 * kDegree, 1e-9);
}

TEST(LocalizeWire, NegativeYawStaysNegative) {
  amcl::Hypothesis hypothesis;
  hypothesis.mean = {0, 0, -45 * kDegree};
  EXPECT_EQ(to_wire(hypothesis).mean[2], -45 * 3600);
}

TEST(LocalizeWire, DataCarriesAtMostTenHypotheses) {
  std::vector<amcl::Hypothesis> hypotheses(12);
  for (std::size_t i = 0; i < hypotheses.size(); ++i) hypotheses[i].mean.x = static_cast<double>(i);
  const protocol::LocalizeData data = localize_data(hypotheses, 3, {12, 500000});
  EXPECT_EQ(data.hypoth_count, 10u);
  EXPECT_EQ(data.hypoths[9].mean[0], 9000);
  EXPECT_EQ(data.pending_count, 3u);
  EXPECT_EQ(data.pending_time_sec, 12u);
  EXPECT_EQ(data.pending_time_usec, 500000u);
  EXPECT_EQ(protocol::encode(data).size(), 14u + 88 * 10);
  EXPECT_EQ(protocol::encode(localize_data({}, 0, {})).size(), 14u);
}

TEST(LocalizeWire, OdometryAndLaserToSiUnits) {
  protocol::PositionData position;
  position.xpos = 1234;
  position.ypos = -500;
  position.yaw = 270;
  const geometry::Pose2 odometry = odometry_pose(position);
  EXPECT_DOUBLE_EQ(odometry.x, 1.234);
  EXPECT_DOUBLE_EQ(odometry.y, -0.5);
  EXPECT_NEAR(odometry.yaw, -90 * kDegree, 1e-12);

  protocol::LaserData laser;
  laser.min_angle = -9000;
  laser.max_angle = 9000;
  laser.resolution = 50;
  laser.range_res = 10;
  laser.range_count = 3;
  laser.ranges[0] = 123;
  laser.ranges[2] = 800;
  const amcl::LaserScan scan = laser_scan(laser, {0.2, 0, 0}, 6.0);
  ASSERT_EQ(scan.ranges.size(), 3u);
  EXPECT_DOUBLE_EQ(scan.ranges[0], 1.23);
  EXPECT_DOUBLE_EQ(scan.ranges[2], 8.0);
  EXPECT_NEAR(scan.bearings[0], -90 * kDegree, 1e-12);
  EXPECT_NEAR(scan.bearings[2], -89 * kDegree, 1e-12);
  EXPECT_DOUBLE_EQ(scan.max_range, 6.0);
  EXPECT_DOUBLE_EQ(scan.sensor_pose.x, 0.2);
}

}  // namespace localize_wire_test
}  // namespace playerkit::localization
