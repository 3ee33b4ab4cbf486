#include "client/typed/position.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/si_units.hpp"

namespace playerkit::client {
namespace position_test {

constexpr double kPi = 3.141592653589793;
constexpr double kOneDegree = 0.017453292519943295;

TEST(TypedPosition, StateGolden) {
  protocol::PositionData d;
  d.xpos = 1500;
  d.ypos = -250;
  d.yaw = -90;
  d.xspeed = 300;
  d.yspeed = -20;
  d.yawspeed = 45;
  d.stall = 1;
  const PositionState s = to_si(d);
  EXPECT_DOUBLE_EQ(s.pose.x, 1.5);
  EXPECT_DOUBLE_EQ(s.pose.y, -0.25);
  EXPECT_DOUBLE_EQ(s.pose.yaw, -1.5707963267948966);
  EXPECT_DOUBLE_EQ(s.velocity.x, 0.3);
  EXPECT_DOUBLE_EQ(s.velocity.y, -0.02);
  EXPECT_DOUBLE_EQ(s.velocity.yaw, 0.7853981633974483);
  EXPECT_TRUE(s.stall);
}

TEST(TypedPosition, StateAgreesWithTheSiJson) {
  protocol::PositionData d;
  d.xpos = -7;
  d.yaw = 359;
  d.yawspeed = -1;
  const auto bytes = protocol::encode(d);
  const auto json = protocol::payload_to_si_json(protocol::kPositionCode, protocol::MessageType::kData, bytes);
  const PositionState s = to_si(protocol::decode<protocol::PositionData>(bytes));
  EXPECT_EQ(json["xpos"].get<double>(), s.pose.x);
  EXPECT_EQ(json["yaw"].get<double>(), s.pose.yaw);
  EXPECT_EQ(json["yawspeed"].get<double>(), s.velocity.yaw);
}

TEST(TypedPosition, CommandGolden) {
  PositionCommand c;
  c.velocity = {0.5, -0.1, kPi / 6};  // 30 deg/s
  c.target = {1.2345, -0.0004, kPi};
  c.motors_on = true;
  const protocol::PositionCommand w = to_wire(c);
  EXPECT_EQ(w.xspeed, 500);
  EXPECT_EQ(w.yspeed, -100);
  EXPECT_EQ(w.yawspeed, 30);
  EXPECT_EQ(w.xpos, 1235);  // 1234.5 mm: halves round away from zero
  EXPECT_EQ(w.ypos, 0);     // -0.4 mm
  EXPECT_EQ(w.yaw, 180);
  EXPECT_EQ(w.state, 1);
  EXPECT_EQ(w.type, 0);
  c.position_mode = true;
  c.motors_on = false;
  EXPECT_EQ(to_wire(c).type, 1);
  EXPECT_EQ(to_wire(c).state, 0);
}

TEST(TypedPosition, CommandRoundTripsWithinOneWireUnit) {
  for (const double v : {-2.71828, -0.0005, 0.0, 0.3333, 1.0, 12.5}) {
    PositionCommand c;
    c.target = {v, -v, v / 3};
    c.velocity = {v / 10, -v / 10, v / 7};
    const PositionCommand back = to_si(protocol::decode<protocol::PositionCommand>(protocol::encode(to_wire(c))));
    EXPECT_NEAR(back.target.x, c.target.x, 0.0005) << v;
    EXPECT_NEAR(back.target.y, c.target.y, 0.0005) << v;
    EXPECT_NEAR(back.target.yaw, c.target.yaw, kOneDegree / 2) << v;
    EXPECT_NEAR(back.velocity.x, c.velocity.x, 0.0005) << v;
    EXPECT_NEAR(back.velocity.y, c.velocity.y, 0.0005) << v;
    EXPECT_NEAR(back.velocity.yaw, c.velocity.yaw, kOneDegree / 2) << v;
  }
}

TEST(TypedPosition, CommandClampsAndRefusesNonFinite) {
  PositionCommand c;
  c.velocity.x = 1e9;  // m/s: 1e12 mm/s does not fit int32
  c.velocity.y = -1e9;
  EXPECT_EQ(to_wire(c).xspeed, std::numeric_limits<std::int32_t>::max());
  EXPECT_EQ(to_wire(c).yspeed, std::numeric_limits<std::int32_t>::min());
  c.velocity.yaw = std::numeric_limits<double>::quiet_NaN();
  try {
    (void)to_wire(c);
    FAIL() << "NaN accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("velocity.yaw"), std::string::npos) << e.what();
  }
  c.velocity.yaw = 0;
  c.target.x = std::numeric_limits<double>::infinity();
  EXPECT_THROW((void)to_wire(c), std::invalid_argument);
}

TEST(TypedPosition, GeometryAndSetOdom) {
  protocol::PositionGeom geom;
  geom.pose = {-100, 50, 90};
  geom.size = {450, 380};
  const PositionGeometry g = to_si(geom);
  EXPECT_DOUBLE_EQ(g.pose.x, -0.1);
  EXPECT_DOUBLE_EQ(g.pose.y, 0.05);
  EXPECT_DOUBLE_EQ(g.pose.yaw, 1.5707963267948966);
  EXPECT_DOUBLE_EQ(g.length, 0.45);
  EXPECT_DOUBLE_EQ(g.width, 0.38);

  const protocol::PositionSetOdomRequest odom = set_odom_request({2.0, -3.5, -kPi / 4});
  EXPECT_EQ(odom.subtype, protocol::kPositionSetOdomReq);
  EXPECT_EQ(odom.x, 2000);
  EXPECT_EQ(odom.y, -3500);
  EXPECT_EQ(odom.theta, -45);
}

}  // namespace position_test
}  // namespace playerkit::client
