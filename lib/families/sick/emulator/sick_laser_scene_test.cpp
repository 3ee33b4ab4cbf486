#include "families/sick/emulator/sick_laser_scene.hpp"

#include "families/sick/emulator/sick_test_room.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace playerkit::emulators {
namespace sick_laser_scene_test {

constexpr double kPi = std::numbers::pi;

TEST(SickLaserScene, RangesInTheRoomAreTheHandComputedOnes) {
  const grid::OccupancyGrid room = testing::box_room();
  SickLaserScene scene({.map = &room});
  const Eigen::Vector2d origin(0.7, 2.1);
  for (int degrees = -180; degrees < 180; degrees += 7) {
    const double angle = degrees * kPi / 180.0;
    const SickBeamReading reading = scene.measure(origin, angle, 8.0);
    EXPECT_TRUE(reading.returned);
    EXPECT_NEAR(reading.range_m, testing::room_range(origin, angle), 1e-9) << degrees << " deg";
  }
  EXPECT_FALSE(scene.measure(origin, 0.0, 1.0).returned);
  EXPECT_DOUBLE_EQ(scene.measure(origin, 0.0, 1.0).range_m, 1.0);
}

TEST(SickLaserScene, UnknownCellsStopBeamsOnlyWhenAskedTo) {
  grid::OccupancyGrid unknown_room = testing::box_room();
  for (int row = 1; row < testing::kRoomCells - 1; ++row) {
    unknown_room.set(40, row, grid::CellState::unknown);  // x 2.00..2.05
  }
  SickLaserScene see_through({.map = &unknown_room});
  SickLaserScene stopped({.map = &unknown_room, .ray_stop = grid::RayStop::occupied_or_unknown});
  EXPECT_NEAR(see_through.measure({1.0, 1.5}, 0.0, 8.0).range_m, 1.95, 1e-9);
  EXPECT_NEAR(stopped.measure({1.0, 1.5}, 0.0, 8.0).range_m, 1.0, 1e-9);
}

TEST(SickLaserScene, ReflectorsBehindAWallAreNotSeen) {
  const grid::OccupancyGrid room = testing::box_room();
  // Beyond the right wall (x 2.95..3.0), and in front of it.
  SickLaserScene scene({.map = &room,
                        .reflectors = {{{3.5, 0.0}, {3.5, 3.0}, 6}, {{2.0, 1.4}, {2.0, 1.6}, 2}}});
  const SickBeamReading towards_front = scene.measure({1.0, 1.5}, 0.0, 8.0);
  EXPECT_NEAR(towards_front.range_m, 1.0, 1e-9);
  EXPECT_EQ(towards_front.reflector_level, 2);
  const SickBeamReading past_front = scene.measure({1.0, 1.0}, 0.0, 8.0);
  EXPECT_NEAR(past_front.range_m, 1.95, 1e-9);
  EXPECT_EQ(past_front.reflector_level, 0);
  // Parallel to the beam: grazing tape is not seen.
  SickLaserScene parallel({.reflectors = {{{1.0, 0.0}, {2.0, 0.0}, 4}}});
  EXPECT_EQ(parallel.measure({0.0, 0.0}, 0.0, 8.0).reflector_level, 0);
}

TEST(SickLaserScene, WithoutAMapEveryBeamReadsTheConstant) {
  SickLaserScene constant({.range_without_map_m = 2.5});
  EXPECT_DOUBLE_EQ(constant.measure({0, 0}, 1.0, 8.0).range_m, 2.5);
  EXPECT_TRUE(constant.measure({0, 0}, 1.0, 8.0).returned);
  EXPECT_DOUBLE_EQ(constant.measure({0, 0}, 1.0, 2.0).range_m, 2.0);  // capped at max range
  SickLaserScene nothing({});
  EXPECT_FALSE(nothing.measure({0, 0}, 1.0, 8.0).returned);
}

}  // namespace sick_laser_scene_test
}  // namespace playerkit::emulators
