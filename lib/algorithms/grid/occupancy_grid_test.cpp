#include "algorithms/grid/occupancy_grid.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace playerkit::grid {
namespace occupancy_grid_test {

TEST(OccupancyGrid, RejectsNonPositiveSizeOrResolution) {
  EXPECT_THROW(OccupancyGrid(0, 5, 0.1, {0, 0}), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(5, -1, 0.1, {0, 0}), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(5, 5, 0.0, {0, 0}), std::invalid_argument);
  EXPECT_THROW(OccupancyGrid(5, 5, -0.1, {0, 0}), std::invalid_argument);
}

TEST(OccupancyGrid, RefusesMoreCellsThanTheLimitBeforeTakingMemory) {
  EXPECT_NO_THROW(OccupancyGrid(1000, 1000, 0.05, Eigen::Vector2d::Zero()));
  try {
    OccupancyGrid(100'000, 100'000, 0.0001, Eigen::Vector2d::Zero());
    FAIL() << "no error";
  } catch (const GridTooLarge& error) {
    EXPECT_EQ(error.width(), 100'000);
    EXPECT_STREQ(error.what(), "a map of 100000 x 100000 cells (10000 million) is more than the limit of 50 million");
  }
  // Just over: 7072 x 7072 = 50,013,184 cells.
  EXPECT_THROW(OccupancyGrid(7072, 7072, 0.05, Eigen::Vector2d::Zero()), GridTooLarge);
}

TEST(OccupancyGrid, FillsAndSetsCells) {
  OccupancyGrid grid(4, 3, 0.5, {1.0, 2.0}, CellState::free);
  EXPECT_EQ(grid.cells().size(), 12u);
  grid.set(3, 2, CellState::occupied);
  EXPECT_EQ(grid.at(3, 2), CellState::occupied);
  EXPECT_EQ(grid.cells()[grid.index(3, 2)], CellState::occupied);
  EXPECT_EQ(grid.index(3, 2), 11u);  // row-major
  EXPECT_EQ(grid.at(0, 0), CellState::free);
}

TEST(OccupancyGrid, WorldToCellFloorsIncludingNegativeCoordinates) {
  const OccupancyGrid grid(10, 10, 0.25, {-1.0, -2.0});
  EXPECT_EQ(grid.world_to_cell({-1.0, -2.0}), Eigen::Vector2i(0, 0));
  EXPECT_EQ(grid.world_to_cell({-0.76, -1.76}), Eigen::Vector2i(0, 0));
  EXPECT_EQ(grid.world_to_cell({-0.75, -1.75}), Eigen::Vector2i(1, 1));
  // Left of / below the origin is a negative cell, not cell 0 (no truncation toward zero).
  EXPECT_EQ(grid.world_to_cell({-1.01, -2.01}), Eigen::Vector2i(-1, -1));
  EXPECT_EQ(grid.world_to_cell({-1.3, -2.6}), Eigen::Vector2i(-2, -3));
  EXPECT_EQ(grid.world_to_cell({1.49, 0.49}), Eigen::Vector2i(9, 9));
  EXPECT_EQ(grid.world_to_cell({1.5, 0.5}), Eigen::Vector2i(10, 10));
}

TEST(OccupancyGrid, CellCentreRoundTrips) {
  const OccupancyGrid grid(8, 6, 0.1, {-0.35, -0.27});
  for (int row = -3; row < 9; ++row) {
    for (int col = -3; col < 11; ++col) {
      const Eigen::Vector2i cell(col, row);
      const Eigen::Vector2d centre = grid.cell_centre(cell);
      EXPECT_NEAR(centre.x(), -0.35 + (col + 0.5) * 0.1, 1e-12);
      EXPECT_NEAR(centre.y(), -0.27 + (row + 0.5) * 0.1, 1e-12);
      EXPECT_EQ(grid.world_to_cell(centre), cell);
      // Points just inside the cell's corners map back to it too.
      EXPECT_EQ(grid.world_to_cell(centre + Eigen::Vector2d(0.0499, -0.0499)), cell);
      EXPECT_EQ(grid.world_to_cell(centre + Eigen::Vector2d(-0.0499, 0.0499)), cell);
    }
  }
}

TEST(OccupancyGrid, CentredPutsTheMapCentreAtTheWorldOrigin) {
  const OccupancyGrid even = OccupancyGrid::centred(500, 400, 0.03);
  EXPECT_NEAR(even.origin().x(), -7.5, 1e-12);
  EXPECT_NEAR(even.origin().y(), -6.0, 1e-12);
  EXPECT_EQ(even.world_to_cell({0.001, 0.001}), Eigen::Vector2i(250, 200));
  EXPECT_EQ(even.world_to_cell({-0.001, -0.001}), Eigen::Vector2i(249, 199));

  const OccupancyGrid odd = OccupancyGrid::centred(3, 5, 1.0, CellState::free);
  EXPECT_NEAR(odd.cell_centre({1, 2}).norm(), 0.0, 1e-12);  // the middle cell sits on the origin
  EXPECT_EQ(odd.at(0, 0), CellState::free);
}

TEST(OccupancyGrid, StateAtWorldIsUnknownOutside) {
  OccupancyGrid grid(2, 2, 1.0, {0, 0}, CellState::free);
  grid.set(1, 0, CellState::occupied);
  EXPECT_EQ(grid.state_at_world({1.5, 0.5}), CellState::occupied);
  EXPECT_EQ(grid.state_at_world({0.5, 1.5}), CellState::free);
  EXPECT_EQ(grid.state_at_world({-0.5, 0.5}), CellState::unknown);
  EXPECT_EQ(grid.state_at_world({0.5, 2.0}), CellState::unknown);
  EXPECT_EQ(grid.state_at_world({1e30, -1e30}), CellState::unknown);
}

}  // namespace occupancy_grid_test
}  // namespace playerkit::grid
