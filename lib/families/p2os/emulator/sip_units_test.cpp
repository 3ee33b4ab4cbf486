#include "families/p2os/emulator/sip_units.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>

namespace playerkit::emulators::p2os {
namespace sip_units_test {

const hardware::p2os::RobotParams& row(std::string_view subclass) {
  return *hardware::p2os::find_robot_params("Pioneer", subclass);
}

TEST(SipUnits, PositionsWrapAt4096BothWays) {
  const auto& p3dx = row("p3dx");  // 0.485 mm per unit
  EXPECT_EQ(position_units(0.0, p3dx), 0);
  EXPECT_EQ(position_units(0.0485, p3dx), 100);
  EXPECT_EQ(position_units(-0.000485, p3dx), 4095);
  EXPECT_EQ(position_units(4096 * 0.000485, p3dx), 0);
  EXPECT_EQ(position_units(4097 * 0.000485, p3dx), 1);
  EXPECT_EQ(position_units(std::numeric_limits<double>::quiet_NaN(), p3dx), 0);
}

TEST(SipUnits, HeadingUsesTheRowsTurn) {
  EXPECT_EQ(heading_units(std::numbers::pi / 2, row("p3dx")), 1024);
  EXPECT_EQ(heading_units(-std::numbers::pi / 2, row("p3dx")), 3072);
  EXPECT_EQ(heading_units(2 * std::numbers::pi - 1e-6, row("p3dx")), 0);
  EXPECT_EQ(heading_units(std::numbers::pi / 2, row("pion1m")), 256);
  EXPECT_EQ(heading_units(-std::numbers::pi / 2, row("pion1m")), 768);
}

TEST(SipUnits, VelocityAndRangeSaturate) {
  EXPECT_EQ(velocity_units(0.2, row("amigo")), 325);  // 200 / 0.6154
  EXPECT_EQ(velocity_units(-0.2, row("p3dx")), -200);
  EXPECT_EQ(velocity_units(1e6, row("p3dx")), 32767);
  EXPECT_EQ(range_units(1.0, row("p2dx")), 3731);  // 1000 / 0.268
  EXPECT_EQ(range_units(-1.0, row("p2dx")), 0);
  EXPECT_EQ(range_units(1e6, row("p2dx")), 65535);
}

}  // namespace sip_units_test
}  // namespace playerkit::emulators::p2os
