#include "client/typed/position3d.hpp"

#include <limits>

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"

namespace playerkit::client {
namespace position3d_test {

constexpr double kArcSecond = 4.84813681109536e-06;  // rad

TEST(TypedPosition3d, StateGolden) {
  protocol::Position3dData d;
  d.xpos = 1000;
  d.ypos = -2000;
  d.zpos = 500;
  d.roll = 3600;      // 1 degree
  d.pitch = -162000;  // -45 degrees
  d.yaw = 648000;     // 180 degrees
  d.xspeed = 100;
  d.zspeed = -10;
  d.yawspeed = 324000;  // 90 deg/s
  d.stall = 1;
  const Position3dState s = to_si(d);
  EXPECT_DOUBLE_EQ(s.pose.x, 1.0);
  EXPECT_DOUBLE_EQ(s.pose.y, -2.0);
  EXPECT_DOUBLE_EQ(s.pose.z, 0.5);
  EXPECT_DOUBLE_EQ(s.pose.roll, 0.017453292519943295);
  EXPECT_DOUBLE_EQ(s.pose.pitch, -0.7853981633974483);
  EXPECT_DOUBLE_EQ(s.pose.yaw, 3.141592653589793);
  EXPECT_DOUBLE_EQ(s.velocity.x, 0.1);
  EXPECT_DOUBLE_EQ(s.velocity.y, 0.0);
  EXPECT_DOUBLE_EQ(s.velocity.z, -0.01);
  EXPECT_DOUBLE_EQ(s.velocity.yaw, 1.5707963267948966);
  EXPECT_TRUE(s.stall);
}

TEST(TypedPosition3d, CommandRoundTripsWithinOneWireUnit) {
  Position3dCommand c;
  c.target = {1.23456, -0.5, 2.0, 0.1, -0.2, 3.0};
  c.velocity = {0.25, -0.0004, 0.0, 0.01, -0.02, 1.5};
  const protocol::Position3dCommand w = to_wire(c);
  EXPECT_EQ(w.xpos, 1235);
  EXPECT_EQ(w.yspeed, 0);
  EXPECT_EQ(w.roll, 20626);  // 0.1 rad = 20626.48 arc-seconds
  const Position3dCommand back = to_si(protocol::decode<protocol::Position3dCommand>(protocol::encode(w)));
  const double angle_step = kArcSecond / 2;
  EXPECT_NEAR(back.target.x, c.target.x, 0.0005);
  EXPECT_NEAR(back.target.y, c.target.y, 0.0005);
  EXPECT_NEAR(back.target.z, c.target.z, 0.0005);
  EXPECT_NEAR(back.target.roll, c.target.roll, angle_step);
  EXPECT_NEAR(back.target.pitch, c.target.pitch, angle_step);
  EXPECT_NEAR(back.target.yaw, c.target.yaw, angle_step);
  EXPECT_NEAR(back.velocity.x, c.velocity.x, 0.0005);
  EXPECT_NEAR(back.velocity.y, c.velocity.y, 0.0005);
  EXPECT_NEAR(back.velocity.roll, c.velocity.roll, angle_step);
  EXPECT_NEAR(back.velocity.pitch, c.velocity.pitch, angle_step);
  EXPECT_NEAR(back.velocity.yaw, c.velocity.yaw, angle_step);
}

TEST(TypedPosition3d, CommandClampsAndRefusesNonFinite) {
  Position3dCommand c;
  c.target.yaw = 1e6;  // rad: 2e11 arc-seconds
  EXPECT_EQ(to_wire(c).yaw, std::numeric_limits<std::int32_t>::max());
  c.velocity.z = -std::numeric_limits<double>::infinity();
  EXPECT_THROW((void)to_wire(c), std::invalid_argument);
}

}  // namespace position3d_test
}  // namespace playerkit::client
