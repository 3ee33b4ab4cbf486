#include "client/typed/fiducial.hpp"

#include <limits>

#include <gtest/gtest.h>

namespace playerkit::client {
namespace fiducial_test {

TEST(TypedFiducial, DetectionsGolden) {
  protocol::FiducialData d;
  d.count = 2;
  d.fiducials[0] = {7, {2500, -30, 90}, {10, 1, 5}};
  d.fiducials[1] = {-1, {800, 45, 0}, {0, 0, 0}};
  d.fiducials[2] = {3, {1, 1, 1}, {1, 1, 1}};  // beyond count
  const auto f = to_si(d);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].id, 7);
  EXPECT_DOUBLE_EQ(f[0].range, 2.5);
  EXPECT_DOUBLE_EQ(f[0].bearing, -0.5235987755982988);
  EXPECT_DOUBLE_EQ(f[0].orientation, 1.5707963267948966);
  EXPECT_DOUBLE_EQ(f[0].range_uncertainty, 0.01);
  EXPECT_DOUBLE_EQ(f[0].bearing_uncertainty, 0.017453292519943295);
  EXPECT_DOUBLE_EQ(f[0].orientation_uncertainty, 0.08726646259971647);
  EXPECT_EQ(f[1].id, -1);
  EXPECT_DOUBLE_EQ(f[1].range, 0.8);
  EXPECT_DOUBLE_EQ(f[1].bearing, 0.7853981633974483);
}

TEST(TypedFiducial, GeometryGolden) {
  protocol::FiducialGeom g;
  g.pose = {200, -100, 180};
  g.size = {50, 60};
  g.fiducial_size = {300, 400};
  const FiducialGeometry s = to_si(g);
  EXPECT_DOUBLE_EQ(s.pose.x, 0.2);
  EXPECT_DOUBLE_EQ(s.pose.y, -0.1);
  EXPECT_DOUBLE_EQ(s.pose.yaw, 3.141592653589793);
  EXPECT_DOUBLE_EQ(s.length, 0.05);
  EXPECT_DOUBLE_EQ(s.width, 0.06);
  EXPECT_DOUBLE_EQ(s.marker_length, 0.3);
  EXPECT_DOUBLE_EQ(s.marker_width, 0.4);
}

TEST(TypedFiducial, FovRoundTripsAndClamps) {
  protocol::FiducialFov wire;
  wire.subtype = protocol::kFiducialGetFov;
  wire.min_range = 300;
  wire.max_range = 8000;
  wire.view_angle = 180;
  const FiducialFov fov = to_si(wire);
  EXPECT_DOUBLE_EQ(fov.min_range, 0.3);
  EXPECT_DOUBLE_EQ(fov.max_range, 8.0);
  EXPECT_DOUBLE_EQ(fov.view_angle, 3.141592653589793);

  protocol::FiducialFov request = set_fov_request(fov);
  EXPECT_EQ(request.subtype, protocol::kFiducialSetFov);
  request.subtype = wire.subtype;
  EXPECT_EQ(request, wire);

  const protocol::FiducialFov clamped = set_fov_request({-1.0, 100.0, 1.0});
  EXPECT_EQ(clamped.min_range, 0);        // uint16 has no negatives
  EXPECT_EQ(clamped.max_range, 65535);    // 100 m does not fit
  EXPECT_EQ(clamped.view_angle, 57);      // 57.3 degrees
  EXPECT_THROW((void)set_fov_request({0, std::numeric_limits<double>::infinity(), 1}), std::invalid_argument);
}

}  // namespace fiducial_test
}  // namespace playerkit::client
