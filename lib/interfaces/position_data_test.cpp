// Golden bytes are written from wire-format.md §5 "position" by hand.
#include "interfaces/position_data.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "protocol/binary_codec.hpp"

namespace playerkit::interfaces {
namespace position_data_test {

TEST(PositionData, HasTheTableLayoutInMillimetresAndDegrees) {
  const protocol::PositionData data = position_data({1.5, -0.25, -std::numbers::pi / 2}, {0.3004, 0.0, 0.5}, true,
                                                    HeadingRange::from_0_to_360);
  // xpos @0, ypos @4, yaw @8, xspeed @12, yspeed @16, yawspeed @20: int32; stall @24.
  const std::vector<std::uint8_t> golden = {0x00, 0x00, 0x05, 0xDC, 0xFF, 0xFF, 0xFF, 0x06, 0x00,
                                            0x00, 0x01, 0x0E, 0x00, 0x00, 0x01, 0x2C, 0x00, 0x00,
                                            0x00, 0x00, 0x00, 0x00, 0x00, 0x1D, 0x01};
  EXPECT_EQ(protocol::encode(data), golden);
  EXPECT_EQ(protocol::decode<protocol::PositionData>(golden), data);
}

TEST(PositionData, TheHeadingRangeIsTheDriversChoice) {
  const geometry::Pose2 facing_right{0.0, 0.0, -std::numbers::pi / 2};
  EXPECT_EQ(position_data(facing_right, {}, false, HeadingRange::from_0_to_360).yaw, 270);
  EXPECT_EQ(position_data(facing_right, {}, false, HeadingRange::from_minus_180_to_180).yaw, -90);
  EXPECT_EQ(position_data(facing_right, {}, false, HeadingRange::from_0_to_360).stall, 0);
}

}  // namespace position_data_test
}  // namespace playerkit::interfaces
