#include "sim/worldfile/world_loader_map.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "sim/worldfile/worldfile_error.hpp"

namespace playerkit::sim::worldfile {
namespace world_loader_map_test {

using grid::CellState;

grid::OccupancyGrid empty_grid() { return grid::OccupancyGrid(40, 40, 0.1, {0.0, 0.0}, CellState::free); }

int occupied_cells(const grid::OccupancyGrid& grid) {
  int count = 0;
  for (const CellState state : grid.cells()) count += state == CellState::occupied;
  return count;
}

TEST(WorldLoaderMapWalls, AnAxisAlignedWallOccupiesTheCellsItOverlaps) {
  grid::OccupancyGrid grid = empty_grid();
  // x in [1.0, 1.5], y in [2.05, 2.25]: columns 10-14, rows 20-22 (row 22 only partly).
  mark_wall(grid, {{1.25, 2.15, 0.0}, {0.5, 0.2}});
  EXPECT_EQ(occupied_cells(grid), 5 * 3);
  EXPECT_EQ(grid.at(10, 20), CellState::occupied);
  EXPECT_EQ(grid.at(14, 22), CellState::occupied);
  EXPECT_EQ(grid.at(9, 21), CellState::free);   // touches x = 1.0 only
  EXPECT_EQ(grid.at(15, 21), CellState::free);  // touches x = 1.5 only
  EXPECT_EQ(grid.at(12, 23), CellState::free);
  // Turned by a right angle it is the same rectangle on its side.
  grid::OccupancyGrid turned = empty_grid();
  mark_wall(turned, {{1.25, 2.15, std::numbers::pi / 2}, {0.2, 0.5}});
  EXPECT_TRUE(std::equal(grid.cells().begin(), grid.cells().end(), turned.cells().begin()));
}

TEST(WorldLoaderMapWalls, ATurnedWallOccupiesExactlyTheCellsItOverlaps) {
  grid::OccupancyGrid grid = empty_grid();
  const WallRectangle wall{{2.0, 2.0, 0.6}, {1.7, 0.13}};
  mark_wall(grid, wall);
  // Independently: a cell is hit if any of a fine lattice of points inside
  // the wall falls inside the cell; a cell whose centre region the wall
  // misses by more than the lattice step is not.
  std::vector<int> hits(grid.cells().size(), 0);
  const double c = std::cos(wall.centre.yaw), s = std::sin(wall.centre.yaw);
  for (double u = -0.85 + 0.0005; u < 0.85; u += 0.001) {
    for (double v = -0.065 + 0.0005; v < 0.065; v += 0.001) {
      const double x = 2.0 + c * u - s * v, y = 2.0 + s * u + c * v;
      ++hits[grid.index(static_cast<int>(std::floor(x / 0.1)), static_cast<int>(std::floor(y / 0.1)))];
    }
  }
  int disagreements = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const bool occupied = grid.cells()[i] == CellState::occupied;
    // A sliver thinner than the lattice step may be missed by the lattice.
    if (occupied != (hits[i] > 0) && !(occupied && hits[i] == 0)) ++disagreements;
    if (hits[i] > 3) {
      EXPECT_TRUE(occupied) << i;
    }
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(occupied_cells(grid), 17);
}

// Does the interior of the turned rectangle overlap the interior of the
// cell? Separating axes, written here apart from the loader's.
bool overlaps(const WallRectangle& wall, double cell_x, double cell_y, double size) {
  const double c = std::cos(wall.centre.yaw), s = std::sin(wall.centre.yaw);
  const double hx = wall.size.x() / 2.0, hy = wall.size.y() / 2.0;
  std::array<Eigen::Vector2d, 4> corners;
  const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int i = 0; i < 4; ++i) {
    const double u = signs[i][0] * hx, v = signs[i][1] * hy;
    corners[i] = {wall.centre.x + c * u - s * v, wall.centre.y + s * u + c * v};
  }
  const std::array<Eigen::Vector2d, 4> cell = {Eigen::Vector2d(cell_x, cell_y), Eigen::Vector2d(cell_x + size, cell_y),
                                               Eigen::Vector2d(cell_x + size, cell_y + size),
                                               Eigen::Vector2d(cell_x, cell_y + size)};
  for (const Eigen::Vector2d& axis : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(c, s),
                                     Eigen::Vector2d(-s, c)}) {
    double a_low = 1e300, a_high = -1e300, b_low = 1e300, b_high = -1e300;
    for (const auto& p : corners) a_low = std::min(a_low, axis.dot(p)), a_high = std::max(a_high, axis.dot(p));
    for (const auto& p : cell) b_low = std::min(b_low, axis.dot(p)), b_high = std::max(b_high, axis.dot(p));
    if (std::min(a_high, b_high) - std::max(a_low, b_low) <= 1e-9 * size) return false;
  }
  return true;
}

TEST(WorldLoaderMapWalls, LongTurnedWallsOccupyEveryCellTheyOverlap) {
  // The loader tests only the cells under a turned wall's extent row by row
  // (its bounding box at 45 degrees is mostly empty); no overlapped cell may
  // be left out, at any angle, for walls long and thin, square, or partly
  // off the grid.
  const std::vector<WallRectangle> walls = {
      {{2.0, 2.0, std::numbers::pi / 4}, {5.0, 0.05}}, {{1.0, 3.0, 0.1}, {6.0, 0.02}},
      {{2.0, 2.0, 1.2}, {0.7, 0.7}},                   {{0.2, 0.3, -0.3}, {3.0, 0.4}},
      {{3.9, 2.0, 2.5}, {2.0, 0.13}},                  {{2.0, 2.0, 1.5707}, {3.3, 0.01}},
  };
  for (const WallRectangle& wall : walls) {
    grid::OccupancyGrid grid = empty_grid();
    mark_wall(grid, wall);
    int disagreements = 0, expected = 0;
    for (int row = 0; row < grid.height(); ++row) {
      for (int col = 0; col < grid.width(); ++col) {
        const bool want = overlaps(wall, col * 0.1, row * 0.1, 0.1);
        expected += want;
        disagreements += want != (grid.at(col, row) == CellState::occupied);
      }
    }
    EXPECT_EQ(disagreements, 0) << "wall at yaw " << wall.centre.yaw;
    EXPECT_GT(expected, 4);
  }
}

TEST(WorldLoaderMapBuild, Stage13WorldsArePositiveAndClosed) {
  MapPlan plan;
  plan.resolution = 0.5;
  plan.positive_quadrant = true;
  plan.minimum_size = {4.0, 3.0};
  plan.must_cover = {{5.2, 1.0}};
  std::vector<std::string> warnings;
  const grid::OccupancyGrid map = build_map(plan, warnings);
  EXPECT_EQ(map.origin(), Eigen::Vector2d::Zero());
  EXPECT_EQ(map.width(), 11);  // 5.2 m
  EXPECT_EQ(map.height(), 6);  // 3 m
  EXPECT_EQ(map.at(0, 0), CellState::free);
  EXPECT_EQ(map.at(1, 1), CellState::occupied);
  EXPECT_EQ(map.at(9, 4), CellState::occupied);
  EXPECT_EQ(map.at(5, 2), CellState::free);
  EXPECT_TRUE(warnings.empty());
}

TEST(WorldLoaderMapBuild, Stage4WorldsHaveAMarginAroundWhatIsThere) {
  MapPlan plan;
  plan.resolution = 0.1;
  plan.walls = {{{-2.0, 3.0, 0.0}, {1.0, 1.0}}};
  plan.must_cover = {{4.0, 3.0}};
  std::vector<std::string> warnings;
  const grid::OccupancyGrid map = build_map(plan, warnings);
  EXPECT_NEAR(map.origin().x(), -3.5, 1e-9);
  EXPECT_NEAR(map.origin().y(), 1.5, 1e-9);
  EXPECT_EQ(map.state_at_world({-2.0, 3.0}), CellState::occupied);
  EXPECT_EQ(map.state_at_world({4.9, 3.9}), CellState::free);
}

TEST(WorldLoaderMapBuild, AHugeWorldGetsCoarserCellsButNeverCoarserThanItsBitmap) {
  MapPlan plan;
  plan.resolution = 0.02;
  plan.walls = {{{0.0, 0.0, 0.0}, {300.0, 300.0}}};  // 15000 x 15000 cells at 2 cm
  std::vector<std::string> warnings;
  const grid::OccupancyGrid map = build_map(plan, warnings);
  EXPECT_LE(static_cast<std::int64_t>(map.width()) * map.height(), grid::kMaxGridCells);
  EXPECT_NEAR(map.resolution(), 0.06, 1e-12);  // 302 m / 0.06 = 5034 cells a side
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("the map's cell is 0.060000 m instead of 0.020000 m"), std::string::npos) << warnings[0];
  // A 0.025 m pixel (the map's cell then) would need 12080 x 12080 cells.
  plan.bitmaps = {{.pixel = 0.025, .corner = {-150.0, -150.0}, .axis_aligned = true}};
  plan.where = SourceLocation{"big.world"};
  try {
    build_map(plan, warnings);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    EXPECT_NE(std::string(error.what()).find("big.world: the world covers 302.000000 x 302.000000 m: at a cell of "
                                             "0.025000 m"),
              std::string::npos)
        << error.what();
  }
}

// Pixels of 0.1 m at x = 0.35 + 0.1 i, y = -0.45 + 0.1 j, and walls that
// are runs of them (as add_bitmap_walls makes them).
MapPlan plan_on_pixels(bool axis_aligned) {
  MapPlan plan;
  plan.resolution = 0.02;
  plan.bitmaps = {{.pixel = 0.1, .corner = {0.35, -0.45}, .axis_aligned = axis_aligned}};
  plan.walls = {{{0.35 + 0.15, -0.45 + 0.05, 0.0}, {0.3, 0.1}},   // pixels (0..2, 0)
                {{0.35 + 0.45, -0.45 + 0.95, 0.0}, {0.1, 0.1}},   // pixel (4, 9)
                {{0.35 + 2.0, -0.45 + 0.35, 0.0}, {4.0, 0.1}}};  // pixels (0..39, 3)
  return plan;
}

TEST(WorldLoaderMapBuild, CellsAreTheBitmapsPixelsWhenThoseAreCoarser) {
  std::vector<std::string> warnings;
  MapPlan plan = plan_on_pixels(true);
  plan.must_cover = {{0.0, -0.5}};  // a robot off the pixels' lattice
  const grid::OccupancyGrid map = build_map(plan, warnings);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.1);
  // The margin of at least 1 m around (0, -0.5) ends on a pixel border.
  EXPECT_NEAR(map.origin().x(), 0.35 - 1.4, 1e-9);
  EXPECT_NEAR(map.origin().y(), -0.45 - 1.1, 1e-9);
  EXPECT_GE(map.origin().x() + map.width() * 0.1, 0.35 + 4.0 + 1.0 - 1e-9);
  // Each wall pixel is one cell, and nothing else is occupied.
  EXPECT_EQ(occupied_cells(map), 3 + 1 + 40);
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 10; ++j) {
      const bool wall = (j == 0 && i <= 2) || (i == 4 && j == 9) || j == 3;
      EXPECT_EQ(map.state_at_world({0.35 + 0.1 * i + 0.05, -0.45 + 0.1 * j + 0.05}) == CellState::occupied, wall)
          << i << "," << j;
    }
  }
  EXPECT_TRUE(warnings.empty());
}

TEST(WorldLoaderMapBuild, ATurnedBitmapKeepsTheWorldsResolution) {
  std::vector<std::string> warnings;
  const grid::OccupancyGrid map = build_map(plan_on_pixels(false), warnings);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.02);
  // The 1 m margin puts cell borders on the walls' edges: 15 x 5, 5 x 5 and
  // 200 x 5 cells of 2 cm.
  EXPECT_NEAR(map.origin().x(), 0.35 - 1.0, 1e-9);
  EXPECT_EQ(occupied_cells(map), 75 + 25 + 1000);
}

TEST(WorldLoaderMapBuild, Stage13BitmapCellsStartAtTheOriginAndKeepTheClosingWall) {
  MapPlan plan;
  plan.resolution = 0.05;
  plan.positive_quadrant = true;
  plan.minimum_size = {4.0, 3.0};
  plan.bitmaps = {{.pixel = 0.1, .corner = {0.0, 0.0}, .axis_aligned = true}};
  plan.walls = {{{1.05, 1.05, 0.0}, {0.1, 0.1}}};
  std::vector<std::string> warnings;
  const grid::OccupancyGrid map = build_map(plan, warnings);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.1);
  EXPECT_EQ(map.origin(), Eigen::Vector2d::Zero());
  EXPECT_EQ(map.width(), 40);
  EXPECT_EQ(map.height(), 30);
  // The closing wall spans [0.05, 0.1] and [3.9, 3.95] in x (one 5 cm cell
  // inside the border), so the 0.1 m cells holding those.
  EXPECT_EQ(map.at(0, 15), CellState::occupied);
  EXPECT_EQ(map.at(39, 15), CellState::occupied);
  EXPECT_EQ(map.at(20, 0), CellState::occupied);
  EXPECT_EQ(map.at(20, 29), CellState::occupied);
  EXPECT_EQ(map.at(1, 15), CellState::free);
  EXPECT_EQ(map.at(38, 15), CellState::free);
  EXPECT_EQ(map.at(10, 10), CellState::occupied);  // the pixel
  EXPECT_EQ(map.at(11, 10), CellState::free);
  // Pixels off the origin's lattice: the cell stays `resolution`.
  plan.bitmaps[0].corner = {0.05, 0.0};
  EXPECT_DOUBLE_EQ(build_map(plan, warnings).resolution(), 0.05);
}

}  // namespace world_loader_map_test
}  // namespace playerkit::sim::worldfile
