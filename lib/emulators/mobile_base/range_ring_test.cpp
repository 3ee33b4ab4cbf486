#include "emulators/mobile_base/range_ring.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace playerkit::emulators::mobile_base {
namespace range_ring_test {

constexpr double kPi = std::numbers::pi;

TEST(RangeRing, ReadsTheWallAlongEachAxisFromTheTransducersPose) {
  // A wall filling x >= 2 m.
  grid::OccupancyGrid map(80, 40, 0.05, {-1.0, -1.0}, grid::CellState::free);
  for (int row = 0; row < 40; ++row) {
    for (int col = 60; col < 80; ++col) map.set(col, row, grid::CellState::occupied);
  }
  const RangeRing ring({{0.2, 0.0, 0.0}, {0.0, 0.2, kPi / 2}});
  // Facing the wall from the origin: the front transducer sits 0.2 m ahead.
  EXPECT_NEAR(ring.range(0, &map, {}, 5.0), 1.8, 0.051);
  // The same transducer with the robot turned left by 90 degrees looks along
  // +y, where nothing stands: the reading is the longest.
  EXPECT_NEAR(ring.range(0, &map, {0.0, 0.0, kPi / 2}, 0.5), 0.5, 1e-9);
  // The side transducer, with the robot turned right, faces the wall.
  EXPECT_NEAR(ring.range(1, &map, {0.0, 0.0, -kPi / 2}, 5.0), 1.8, 0.051);
  EXPECT_EQ(ring.range(0, nullptr, {}, 3.0), 3.0) << "no map: every reading is the longest";
}

TEST(RangeRing, WorldPoseComposesTheRobotsPose) {
  const RangeRing ring({{0.1, 0.0, kPi / 2}});
  const geometry::Pose2 world = ring.world_pose(0, {1.0, 2.0, kPi / 2});
  EXPECT_NEAR(world.x, 1.0, 1e-12);
  EXPECT_NEAR(world.y, 2.1, 1e-12);
  EXPECT_NEAR(world.yaw, kPi, 1e-12);
  EXPECT_THROW((void)ring.world_pose(1, {}), std::out_of_range);
}

TEST(EvenlySpacedRing, FirstTransducerAtTheGivenHeadingTheRestInOrder) {
  const auto clockwise = evenly_spaced_ring(4, 0.2, kPi / 2, RingOrder::clockwise);
  ASSERT_EQ(clockwise.size(), 4u);
  EXPECT_NEAR(clockwise[0].y, 0.2, 1e-12);
  EXPECT_NEAR(clockwise[1].yaw, 0.0, 1e-12);
  EXPECT_NEAR(clockwise[1].x, 0.2, 1e-12);
  const auto counter = evenly_spaced_ring(4, 0.2, 0.0, RingOrder::counter_clockwise);
  EXPECT_NEAR(counter[1].yaw, kPi / 2, 1e-12);
  EXPECT_TRUE(evenly_spaced_ring(0, 0.2, 0.0, RingOrder::clockwise).empty());
}

}  // namespace range_ring_test
}  // namespace playerkit::emulators::mobile_base
