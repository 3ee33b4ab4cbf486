#include "emulators/mobile_base/obstacle_search.hpp"

#include <gtest/gtest.h>

namespace playerkit::emulators::mobile_base {
namespace obstacle_search_test {

TEST(NearestObstacle, DistanceToTheCellsNearestPoint) {
  grid::OccupancyGrid map(10, 10, 0.1, {0.0, 0.0}, grid::CellState::free);
  map.set(7, 5, grid::CellState::occupied);  // spans x [0.7, 0.8), y [0.5, 0.6)
  map.set(2, 2, grid::CellState::unknown);   // not an obstacle
  const auto found = nearest_obstacle(map, {0.5, 0.55}, 0.3);
  ASSERT_TRUE(found.has_value());
  EXPECT_NEAR(found->distance, 0.2, 1e-12);
  EXPECT_NEAR(found->point.x(), 0.7, 1e-12);
  EXPECT_NEAR(found->point.y(), 0.55, 1e-12);
  EXPECT_FALSE(nearest_obstacle(map, {0.5, 0.55}, 0.2).has_value()) << "exactly at the radius is clear";
  EXPECT_FALSE(nearest_obstacle(map, {0.25, 0.25}, 0.2).has_value());
  EXPECT_FALSE(nearest_obstacle(map, {50.0, 50.0}, 1.0).has_value()) << "far outside the grid";
  EXPECT_FALSE(nearest_obstacle(grid::OccupancyGrid{}, {0.0, 0.0}, 1.0).has_value());
}

}  // namespace obstacle_search_test
}  // namespace playerkit::emulators::mobile_base
