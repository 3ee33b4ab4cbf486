#include "families/flockofbirds/driver/position3d_mapping.hpp"

#include <gtest/gtest.h>

namespace playerkit::drivers::flockofbirds {
namespace position3d_mapping_test {

namespace fob = hardware::flockofbirds;

// flockofbirds.md §3's example, from the record of §1.1 read at Ascension's
// full scale and rounded (1.5: 304, -152, -76, 324009, 1133995, 35992).
TEST(Position3dMapping, TheSheetsExample) {
  const auto words = fob::decode_record(fob::Record{0xAA, 0x15, 0x2A, 0x75, 0x2A, 0x05, 0x00, 0x20, 0x00, 0x70, 0x47, 0x03});
  ASSERT_TRUE(words);
  const protocol::Position3dData data = position3d_from_bird(fob::pose_from_words(*words, fob::PositionScaling::inches_36));
  EXPECT_EQ(data.xpos, 305);
  EXPECT_EQ(data.ypos, -152);
  EXPECT_EQ(data.zpos, -76);  // Z's sign inverted, as in 1.5
  EXPECT_EQ(data.yaw, 324000);
  EXPECT_EQ(data.pitch, 1134000);  // -45 deg as 315
  EXPECT_EQ(data.roll, 35991);
  EXPECT_EQ(data.xspeed, 0);
  EXPECT_EQ(data.yawspeed, 0);
  EXPECT_EQ(data.stall, 0);
}

TEST(Position3dMapping, AnglesFrom0To360) {
  EXPECT_EQ(arc_seconds_0_to_360(0), 0);
  EXPECT_EQ(arc_seconds_0_to_360(-90), 270 * 3600);
  EXPECT_EQ(arc_seconds_0_to_360(179.99), 647964);
  EXPECT_EQ(arc_seconds_0_to_360(-180), 180 * 3600);
  EXPECT_EQ(arc_seconds_0_to_360(-0.00001), 0);  // rounds to a full turn: 0, never 1296000
  EXPECT_EQ(arc_seconds_0_to_360(360), 0);
}

}  // namespace position3d_mapping_test
}  // namespace playerkit::drivers::flockofbirds
