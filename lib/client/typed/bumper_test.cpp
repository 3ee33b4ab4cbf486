#include "client/typed/bumper.hpp"

#include <gtest/gtest.h>

namespace playerkit::client {
namespace bumper_test {

TEST(TypedBumper, PressedFlags) {
  protocol::BumperData d;
  d.bumper_count = 3;
  d.bumpers[0] = 0;
  d.bumpers[1] = 1;
  d.bumpers[2] = 255;
  d.bumpers[3] = 1;  // beyond bumper_count
  EXPECT_EQ(to_si(d).pressed, (std::vector<bool>{false, true, true}));
}

TEST(TypedBumper, GeometryGolden) {
  protocol::BumperGeom g;
  g.bumper_count = 1;
  g.bumper_def[0] = {-50, 120, 90, 200, 250};
  const auto defs = to_si(g);
  ASSERT_EQ(defs.size(), 1u);
  EXPECT_DOUBLE_EQ(defs[0].pose.x, -0.05);
  EXPECT_DOUBLE_EQ(defs[0].pose.y, 0.12);
  EXPECT_DOUBLE_EQ(defs[0].pose.yaw, 1.5707963267948966);
  EXPECT_DOUBLE_EQ(defs[0].length, 0.2);
  EXPECT_DOUBLE_EQ(defs[0].radius, 0.25);
}

}  // namespace bumper_test
}  // namespace playerkit::client
