#include "algorithms/wavefront/clearance_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace playerkit::wavefront {
namespace clearance_map_test {

using grid::CellState;
using grid::OccupancyGrid;

// The definition: the nearest point of any occupied or unknown square, or
// of the outside of the grid.
double brute_force(const OccupancyGrid& grid, const Eigen::Vector2d& p) {
  const double res = grid.resolution();
  const Eigen::Vector2d lo = grid.origin();
  const Eigen::Vector2d hi = lo + Eigen::Vector2d(grid.width(), grid.height()) * res;
  if ((p.array() <= lo.array()).any() || (p.array() >= hi.array()).any()) return 0.0;
  double best = std::min({p.x() - lo.x(), hi.x() - p.x(), p.y() - lo.y(), hi.y() - p.y()});
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (grid.at(col, row) == CellState::free) continue;
      const Eigen::Vector2d a = lo + Eigen::Vector2d(col, row) * res;
      const Eigen::Vector2d b = a + Eigen::Vector2d::Constant(res);
      const double dx = std::max({a.x() - p.x(), 0.0, p.x() - b.x()});
      const double dy = std::max({a.y() - p.y(), 0.0, p.y() - b.y()});
      best = std::min(best, std::hypot(dx, dy));
    }
  }
  return best;
}

OccupancyGrid random_grid(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> pick(0, 99);
  OccupancyGrid grid(width, height, 0.1, {-1.0, 2.0}, CellState::free);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const int roll = pick(random);
      if (roll < 3) grid.set(col, row, CellState::occupied);
      if (roll == 3) grid.set(col, row, CellState::unknown);
    }
  }
  return grid;
}

TEST(ClearanceMap, CellCentresMatchTheDefinitionUpToTheReach) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const OccupancyGrid grid = random_grid(37, 23, seed);
    const ClearanceMap map(grid, 0.45);
    ASSERT_EQ(map.reach_cells(), 5);
    for (int row = 0; row < grid.height(); ++row) {
      for (int col = 0; col < grid.width(); ++col) {
        const double expected = std::min(brute_force(grid, grid.cell_centre({col, row})), map.reach());
        ASSERT_NEAR(map.at(col, row), expected, 1e-9) << "seed " << seed << " cell " << col << "," << row;
        // Stored as whole quarter squares.
        const float q = map.quarter_squared(col, row);
        ASSERT_EQ(q, std::round(q));
      }
    }
  }
}

TEST(ClearanceMap, UnknownCellsAndTheGridEdgeCountAsObstacles) {
  OccupancyGrid grid(21, 21, 0.1, {0.0, 0.0}, CellState::free);
  grid.set(10, 15, CellState::unknown);
  const ClearanceMap map(grid, 2.0);
  // Cell (10, 10): 4.5 cells to the unknown square's lower edge; 10.5 to the
  // grid edges.
  EXPECT_NEAR(map.at(10, 10), 0.45, 1e-12);
  EXPECT_NEAR(map.at(10, 2), 0.25, 1e-12);  // the bottom edge
  EXPECT_NEAR(map.at(0, 0), 0.05, 1e-12);
  EXPECT_TRUE(map.is_obstacle(-1, 3));
  EXPECT_TRUE(map.is_obstacle(10, 15));
  EXPECT_FALSE(map.is_obstacle(10, 14));
}

TEST(ClearanceMap, PointAndSegmentQueriesAreExact) {
  const OccupancyGrid grid = random_grid(30, 30, 7);
  const ClearanceMap map(grid, 0.3);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> x(-1.2, 2.2), y(1.8, 5.2);
  for (int trial = 0; trial < 80; ++trial) {
    const Eigen::Vector2d a{x(random), y(random)};
    const Eigen::Vector2d b = a + Eigen::Vector2d(x(random) - 0.5, y(random) - 3.5) * 0.3;
    for (const double limit : {0.15, 0.6}) {
      ASSERT_NEAR(map.point_clearance(a, limit), std::min(brute_force(grid, a), limit), 1e-9);
      // Dense samples bracket the segment's distance: never below it, and at
      // most half a sample spacing above it.
      constexpr int kSamples = 200;
      double sampled = limit;
      for (int k = 0; k <= kSamples; ++k) sampled = std::min(sampled, brute_force(grid, a + (b - a) * k / kSamples));
      const double exact = map.segment_clearance(a, b, limit);
      ASSERT_LE(exact, sampled + 1e-12);
      ASSERT_GE(exact, sampled - 0.5 * (b - a).norm() / kSamples - 1e-12);
      ASSERT_EQ(map.segment_keeps(a, b, 0.12), map.segment_clearance(a, b, 0.12) >= 0.12 - kClearanceTolerance);
    }
  }
}

TEST(ClearanceMap, ASegmentThroughAWallTouchesIt) {
  OccupancyGrid grid(20, 20, 0.1, {0.0, 0.0}, CellState::free);
  for (int row = 0; row < 20; ++row) grid.set(10, row, CellState::occupied);
  const ClearanceMap map(grid, 0.5);
  EXPECT_EQ(map.segment_clearance({0.5, 1.0}, {1.5, 1.0}, 0.5), 0.0);
  EXPECT_NEAR(map.segment_clearance({0.5, 1.0}, {0.8, 1.2}, 0.5), 0.2, 1e-12);
  EXPECT_FALSE(map.segment_keeps({0.5, 1.0}, {0.8, 1.2}, 0.21));
  EXPECT_TRUE(map.segment_keeps({0.5, 1.0}, {0.8, 1.2}, 0.2));
  // Points outside the grid touch the unknown outside.
  EXPECT_EQ(map.point_clearance({-3.0, 1.0}, 0.5), 0.0);
  const Eigen::Vector2d path[] = {{0.5, 0.5}, {0.5, 1.5}, {0.7, 1.5}};
  EXPECT_NEAR(map.polyline_clearance(path, 1.0), 0.3, 1e-12);
}

TEST(ClearanceMap, RejectsWhatItCannotHold) {
  const OccupancyGrid grid(4, 4, 0.1, {0.0, 0.0}, CellState::free);
  EXPECT_THROW(ClearanceMap(grid, -1.0), std::invalid_argument);
  EXPECT_THROW(ClearanceMap(grid, 1000.0), std::invalid_argument);
  EXPECT_THROW(ClearanceMap(OccupancyGrid(), 1.0), std::invalid_argument);
}

}  // namespace clearance_map_test
}  // namespace playerkit::wavefront
