#include "algorithms/grid/ray_cast.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace playerkit::grid {
namespace ray_cast_test {

constexpr double kResolution = 0.05;

// A 10 m x 10 m centred grid, free inside the square |x|, |y| < half_side and
// occupied outside it. half_side on a cell border makes the walls exact.
OccupancyGrid square_room(double half_side) {
  OccupancyGrid grid = OccupancyGrid::centred(200, 200, kResolution, CellState::free);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const Eigen::Vector2d centre = grid.cell_centre({col, row});
      if (std::abs(centre.x()) > half_side || std::abs(centre.y()) > half_side) {
        grid.set(col, row, CellState::occupied);
      }
    }
  }
  return grid;
}

// Distance from an inside point to the square's border along `angle`.
double distance_to_square(const Eigen::Vector2d& from, double angle, double half_side) {
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  double best = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 2; ++axis) {
    if (direction[axis] == 0.0) continue;
    const double wall = direction[axis] > 0 ? half_side : -half_side;
    best = std::min(best, (wall - from[axis]) / direction[axis]);
  }
  return best;
}

TEST(CastRay, MatchesAnalyticAxisAlignedWallsAtManyAngles) {
  const double half_side = 4.0;  // -5 + 180 cells * 0.05: a cell border
  const OccupancyGrid grid = square_room(half_side);
  const Eigen::Vector2d origins[] = {{0.0, 0.0}, {0.37, -1.23}, {-3.11, 2.96}, {3.9, 3.9}};
  for (const Eigen::Vector2d& origin : origins) {
    for (int i = 0; i < 720; ++i) {
      const double angle = -std::numbers::pi + i * (2.0 * std::numbers::pi / 720.0) + 1e-4;
      const double expected = distance_to_square(origin, angle, half_side);
      const double range = cast_ray(grid, origin, angle, 20.0);
      // The walls start on cell borders, so the entry distance is exact.
      ASSERT_NEAR(range, expected, 1e-9) << "origin " << origin.transpose() << " angle " << angle;
    }
  }
}

TEST(CastRay, DiagonalWallWithinOneCell) {
  // Occupied where x + y >= 2.5: a wall not aligned with the grid.
  OccupancyGrid grid = OccupancyGrid::centred(200, 200, kResolution, CellState::free);
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const Eigen::Vector2d c = grid.cell_centre({col, row});
      if (c.x() + c.y() >= 2.5) grid.set(col, row, CellState::occupied);
    }
  }
  const Eigen::Vector2d origin(-0.4, 0.3);
  int rays = 0;
  for (double angle = -0.7; angle < 2.2; angle += 0.005) {
    // Within 45 degrees of the wall's normal a staircase error of half a
    // cell diagonal is at most one cell along the ray.
    const double along = std::cos(angle) + std::sin(angle);
    if (along < 1.0) continue;
    const double expected = (2.5 - origin.x() - origin.y()) / along;
    if (expected > 4.0) continue;  // keep inside the grid
    EXPECT_NEAR(cast_ray(grid, origin, angle, 20.0, RayStop::occupied), expected, kResolution)
        << angle;
    ++rays;
  }
  EXPECT_GT(rays, 250);
}

TEST(CastRay, ReturnsMaxRangeWhenNothingIsHit) {
  const OccupancyGrid room = square_room(4.0);
  EXPECT_DOUBLE_EQ(cast_ray(room, {0, 0}, 0.3, 2.5), 2.5);  // wall beyond max_range

  const OccupancyGrid open = OccupancyGrid::centred(100, 100, 0.1, CellState::free);
  for (double angle = 0.0; angle < 6.28; angle += 0.1) {
    EXPECT_DOUBLE_EQ(cast_ray(open, {0.2, -0.1}, angle, 30.0), 30.0);  // leaves the grid
  }
  EXPECT_DOUBLE_EQ(cast_ray(open, {50.0, 0.0}, std::numbers::pi, 80.0), 80.0);  // starts outside
  EXPECT_DOUBLE_EQ(cast_ray(OccupancyGrid{}, {0, 0}, 0.0, 7.0), 7.0);
}

TEST(CastRay, StartingInAStoppingCellGivesZero) {
  const OccupancyGrid room = square_room(4.0);
  EXPECT_DOUBLE_EQ(cast_ray(room, {4.5, 0.0}, 2.0, 10.0), 0.0);
}

TEST(CastRay, UnknownStopsOnlyWhenAsked) {
  OccupancyGrid grid(100, 1, 0.1, {0.0, 0.0}, CellState::free);
  for (int col = 30; col < 40; ++col) grid.set(col, 0, CellState::unknown);
  grid.set(70, 0, CellState::occupied);
  EXPECT_NEAR(cast_ray(grid, {0.05, 0.05}, 0.0, 9.0), 2.95, 1e-9);
  EXPECT_NEAR(cast_ray(grid, {0.05, 0.05}, 0.0, 9.0, RayStop::occupied), 6.95, 1e-9);
}

// True when the segment from a to b meets the closed cell square (clipping).
bool segment_touches_cell(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const Eigen::Vector2i& cell, double tolerance) {
  double t0 = 0.0, t1 = 1.0;
  const Eigen::Vector2d d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    const double low = cell[axis] - tolerance, high = cell[axis] + 1.0 + tolerance;
    if (d[axis] == 0.0) {
      if (a[axis] < low || a[axis] > high) return false;
      continue;
    }
    double enter = (low - a[axis]) / d[axis], leave = (high - a[axis]) / d[axis];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
  }
  return t0 <= t1;
}

TEST(TraceCells, VisitsAConnectedSequenceOfCrossedCells) {
  // Unit cells with the origin at (0, 0), so cell indices are world floors.
  const OccupancyGrid grid(20, 20, 1.0, {0.0, 0.0});
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-5.0, 25.0);  // partly outside the grid
  for (int trial = 0; trial < 500; ++trial) {
    const Eigen::Vector2d from{coordinate(random), coordinate(random)};
    const Eigen::Vector2d to{coordinate(random), coordinate(random)};
    std::vector<Eigen::Vector2i> cells;
    trace_cells(grid, from, to, [&](const Eigen::Vector2i& cell) {
      cells.push_back(cell);
      return true;
    });
    ASSERT_FALSE(cells.empty());
    const Eigen::Vector2i first = grid.world_to_cell(from), last = grid.world_to_cell(to);
    EXPECT_EQ(cells.front(), first);
    EXPECT_EQ(cells.back(), last);
    EXPECT_EQ(cells.size(),
              static_cast<std::size_t>(std::abs(last.x() - first.x()) +
                                       std::abs(last.y() - first.y()) + 1));
    for (std::size_t i = 1; i < cells.size(); ++i) {
      const Eigen::Vector2i step = cells[i] - cells[i - 1];
      ASSERT_EQ(std::abs(step.x()) + std::abs(step.y()), 1) << "diagonal or repeated step";
    }
    for (const Eigen::Vector2i& cell : cells) {
      EXPECT_TRUE(segment_touches_cell(from, to, cell, 1e-9)) << cell.transpose();
    }
  }
}

TEST(TraceCells, ThroughACornerStepsThroughANeighbour) {
  const OccupancyGrid grid(10, 10, 1.0, {0.0, 0.0});
  std::vector<Eigen::Vector2i> cells;
  trace_cells(grid, {0.5, 0.5}, {2.5, 2.5}, [&](const Eigen::Vector2i& cell) {
    cells.push_back(cell);
    return true;
  });
  const std::vector<Eigen::Vector2i> expected = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}};
  EXPECT_EQ(cells, expected);
}

TEST(TraceCells, StopsWhenTheVisitorSaysSo) {
  const OccupancyGrid grid(10, 10, 0.5, {-2.5, -2.5});
  std::vector<Eigen::Vector2i> cells;
  trace_cells(grid, {-2.4, 0.1}, {2.4, 0.1}, [&](const Eigen::Vector2i& cell) {
    cells.push_back(cell);
    return cells.size() < 3;
  });
  const std::vector<Eigen::Vector2i> expected = {{0, 5}, {1, 5}, {2, 5}};
  EXPECT_EQ(cells, expected);
}

TEST(TraceCells, SameCellIsVisitedOnce) {
  const OccupancyGrid grid(10, 10, 0.5, {0.0, 0.0});
  int visits = 0;
  trace_cells(grid, {1.1, 1.1}, {1.2, 1.4}, [&](const Eigen::Vector2i& cell) {
    EXPECT_EQ(cell, Eigen::Vector2i(2, 2));
    ++visits;
    return true;
  });
  EXPECT_EQ(visits, 1);
}

}  // namespace ray_cast_test
}  // namespace playerkit::grid
