// The status-to-Player mapping of segwayrmp.md §3, with values worked by hand.
#include "families/segwayrmp/driver/rmp_mapping.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace playerkit::drivers::segwayrmp {
namespace rmp_mapping_test {

namespace rmp = hardware::segwayrmp;

TEST(RmpMapping, PositionInMillimetresAndWholeDegreesWithTheYawRateTurnedAround) {
  const rmp::Status status{.left_wheel_velocity = 166, .right_wheel_velocity = 170, .yaw_rate = -78};
  const rmp::OdometryPose pose{.x = 1.2345, .y = -0.0019, .theta = std::numbers::pi / 2 + 0.01};
  const protocol::PositionData data = position_data(status, pose);
  EXPECT_EQ(data.xpos, 1234);  // truncated, as 1.5
  EXPECT_EQ(data.ypos, -1);
  EXPECT_EQ(data.yaw, 90);
  EXPECT_EQ(data.xspeed, 506);   // (166 + 170) / 332 * 1000 / 2 = 506.02
  EXPECT_EQ(data.yawspeed, 10);  // -(-78 / 7.8): the RMP counts clockwise
  EXPECT_EQ(data.yspeed, 0);
  EXPECT_EQ(data.stall, 0);
}

TEST(RmpMapping, Position3dAnglesInArcSecondsAttitudeWithinZeroTo360) {
  const rmp::Status status{.pitch = -78, .pitch_rate = 39, .roll = 78, .roll_rate = -39, .yaw_rate = 78};
  const protocol::Position3dData data = position3d_data(status, {.x = 0.5, .y = 0, .theta = 0.5});
  EXPECT_EQ(data.xpos, 500);
  EXPECT_EQ(data.pitch, 350 * 3600);  // -10 degrees
  EXPECT_EQ(data.roll, 10 * 3600);
  EXPECT_EQ(data.pitchspeed, 5 * 3600);
  EXPECT_EQ(data.rollspeed, -5 * 3600);
  EXPECT_EQ(data.yawspeed, -10 * 3600);
  EXPECT_EQ(data.yaw, static_cast<std::int32_t>(0.5 * 180 / std::numbers::pi * 3600));
}

TEST(RmpMapping, PowerIsThePercentageOfA72VoltPack) {
  EXPECT_EQ(power_data({.battery = 100}).charge, 720);
  EXPECT_EQ(power_data({.battery = 85}).charge, 612);
}

}  // namespace rmp_mapping_test
}  // namespace playerkit::drivers::segwayrmp
