#include "algorithms/grid/distance_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace playerkit::grid {
namespace distance_map_test {

struct Cell {
  int col, row;
};

// The cells distances are measured to.
std::vector<Cell> source_cells(const OccupancyGrid& grid, DistanceTo sources = DistanceTo::occupied) {
  std::vector<Cell> cells;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const CellState state = grid.at(col, row);
      if (sources == DistanceTo::occupied ? state == CellState::occupied : state != CellState::free) {
        cells.push_back({col, row});
      }
    }
  }
  return cells;
}

// The definition, O(sources) a cell.
double brute_force_distance(const std::vector<Cell>& sources, double resolution, int col, int row,
                            double max_distance) {
  double best_squared = std::numeric_limits<double>::infinity();
  for (const Cell& source : sources) {
    const double dc = source.col - col, dr = source.row - row;
    best_squared = std::min(best_squared, dc * dc + dr * dr);
  }
  return std::min(std::sqrt(best_squared) * resolution, max_distance);
}

double brute_force_distance(const OccupancyGrid& grid, int col, int row, double max_distance,
                            DistanceTo sources = DistanceTo::occupied) {
  return brute_force_distance(source_cells(grid, sources), grid.resolution(), col, row, max_distance);
}

// Distances are stored as float; exact means "the float nearest the true value".
double as_stored(double distance) { return static_cast<double>(static_cast<float>(distance)); }

OccupancyGrid random_grid(int width, int height, double occupied_fraction, unsigned seed) {
  std::mt19937 random(seed);
  std::bernoulli_distribution occupied(occupied_fraction);
  std::uniform_int_distribution<int> other(0, 1);
  OccupancyGrid grid(width, height, 0.1, {-1.0, 2.0});
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      grid.set(col, row,
               occupied(random) ? CellState::occupied
                                : (other(random) ? CellState::free : CellState::unknown));
    }
  }
  return grid;
}

TEST(DistanceMap, MatchesBruteForceOnRandomGrids) {
  struct Case {
    int width, height;
    double fraction;
  };
  const Case cases[] = {{37, 23, 0.02}, {23, 37, 0.1}, {50, 50, 0.005}, {1, 40, 0.05},
                        {40, 1, 0.05},  {64, 17, 0.3}};
  unsigned seed = 1;
  for (const Case& c : cases) {
    const OccupancyGrid grid = random_grid(c.width, c.height, c.fraction, seed++);
    const double max_distance = 100.0;  // far above any distance here: no capping
    const DistanceMap map(grid, max_distance);
    ASSERT_EQ(map.width(), c.width);
    ASSERT_EQ(map.height(), c.height);
    for (int row = 0; row < c.height; ++row) {
      for (int col = 0; col < c.width; ++col) {
        EXPECT_EQ(map.at(col, row), as_stored(brute_force_distance(grid, col, row, max_distance)))
            << c.width << "x" << c.height << " at " << col << "," << row;
      }
    }
  }
}

// With a small cap most of a sparse row is out of reach: the row pass runs
// only on stretches around the cells near a source, split where those lie
// far apart. Against brute force, with stretches at the row's ends, apart
// by exactly and by just over twice the cap.
TEST(DistanceMap, MatchesBruteForceWhenTheCapSplitsRows) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const OccupancyGrid grid = random_grid(230, 30, 0.004, seed);
    const auto sources = source_cells(grid);
    for (const double max_distance : {0.05, 0.3, 0.55, 1.2}) {
      const DistanceMap map(grid, max_distance);
      for (int row = 0; row < grid.height(); ++row) {
        for (int col = 0; col < grid.width(); ++col) {
          ASSERT_EQ(map.at(col, row),
                    as_stored(brute_force_distance(sources, grid.resolution(), col, row, max_distance)))
              << "seed " << seed << " cap " << max_distance << " at " << col << "," << row;
        }
      }
    }
  }
  // Two obstacles in one row, at gaps around twice the cap (7 cells at 0.55 m).
  for (int gap = 10; gap <= 18; ++gap) {
    OccupancyGrid grid(60, 1, 0.1, {0.0, 0.0}, CellState::free);
    grid.set(0, 0, CellState::occupied);
    grid.set(gap, 0, CellState::occupied);
    grid.set(59, 0, CellState::occupied);
    const DistanceMap map(grid, 0.55);
    for (int col = 0; col < 60; ++col) {
      ASSERT_EQ(map.at(col, 0), as_stored(brute_force_distance(grid, col, 0, 0.55))) << "gap " << gap << " col " << col;
    }
  }
}

TEST(DistanceMap, UnknownCellsAreSourcesOnlyWhenAsked) {
  // Mostly free with a few obstacles and a few unknown cells, so the two
  // modes give different answers almost everywhere.
  std::mt19937 random(5);
  std::discrete_distribution<int> state({0.96, 0.02, 0.02});  // free, unknown, occupied
  OccupancyGrid grid(41, 29, 0.1, {0.0, 0.0});
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) grid.set(col, row, static_cast<CellState>(state(random) - 1));
  }
  const DistanceMap to_occupied(grid, 100.0);
  const DistanceMap to_occupied_explicit(grid, 100.0, DistanceTo::occupied);
  const DistanceMap to_not_free(grid, 100.0, DistanceTo::occupied_or_unknown);
  int unknown_cells = 0, differing = 0;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      EXPECT_EQ(to_occupied.at(col, row), as_stored(brute_force_distance(grid, col, row, 100.0)));
      EXPECT_EQ(to_occupied_explicit.at(col, row), to_occupied.at(col, row));
      EXPECT_EQ(to_not_free.at(col, row),
                as_stored(brute_force_distance(grid, col, row, 100.0, DistanceTo::occupied_or_unknown)));
      if (grid.at(col, row) == CellState::unknown) {
        ++unknown_cells;
        EXPECT_EQ(to_not_free.at(col, row), 0.0);
        EXPECT_GT(to_occupied.at(col, row), 0.0);
      }
      differing += to_not_free.at(col, row) < to_occupied.at(col, row);
    }
  }
  EXPECT_GT(unknown_cells, 10);
  EXPECT_GT(differing, 200);  // the unknown cells really changed the field
}

TEST(DistanceMap, AllUnknownMapIsZeroOnlyInTheNotFreeMode) {
  const OccupancyGrid grid(6, 4, 0.5, {0, 0}, CellState::unknown);
  const DistanceMap to_occupied(grid, 3.0);
  const DistanceMap to_not_free(grid, 3.0, DistanceTo::occupied_or_unknown);
  EXPECT_DOUBLE_EQ(to_occupied.at(2, 2), 3.0);
  EXPECT_DOUBLE_EQ(to_not_free.at(2, 2), 0.0);
}

TEST(DistanceMap, CapsAtMaxDistance) {
  const OccupancyGrid grid = random_grid(60, 45, 0.003, 99);
  const double max_distance = 0.75;  // 7.5 cells
  const DistanceMap map(grid, max_distance);
  int capped = 0;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const double expected = brute_force_distance(grid, col, row, max_distance);
      EXPECT_EQ(map.at(col, row), as_stored(expected));
      EXPECT_LE(map.at(col, row), max_distance);
      capped += expected == max_distance;
    }
  }
  EXPECT_GT(capped, 100);  // the cap was actually exercised
}

TEST(DistanceMap, SingleObstacleGivesEuclideanDistances) {
  OccupancyGrid grid(30, 20, 0.05, {0, 0}, CellState::free);
  grid.set(4, 7, CellState::occupied);
  const DistanceMap map(grid, 10.0);
  EXPECT_DOUBLE_EQ(map.at(4, 7), 0.0);
  EXPECT_NEAR(map.at(7, 11), 0.25, 1e-6);  // a 3-4-5 triangle
  EXPECT_NEAR(map.at(29, 19), std::hypot(25, 12) * 0.05, 1e-6);
}

TEST(DistanceMap, EmptyMapIsMaxDistanceEverywhere) {
  const OccupancyGrid grid(15, 9, 0.1, {0, 0}, CellState::free);
  const DistanceMap map(grid, 2.0);
  for (int row = 0; row < 9; ++row) {
    for (int col = 0; col < 15; ++col) EXPECT_DOUBLE_EQ(map.at(col, row), 2.0);
  }
  const DistanceMap from_nothing(OccupancyGrid{}, 3.0);
  EXPECT_DOUBLE_EQ(from_nothing.at_world({0, 0}), 3.0);
}

TEST(DistanceMap, AtWorldLooksUpTheCellAndIsMaxOutside) {
  OccupancyGrid grid(10, 10, 0.5, {-2.5, -2.5}, CellState::free);
  grid.set(5, 5, CellState::occupied);  // spans [0, 0.5) x [0, 0.5)
  const DistanceMap map(grid, 4.0);
  EXPECT_DOUBLE_EQ(map.at_world({0.25, 0.25}), 0.0);
  EXPECT_NEAR(map.at_world({1.2, 0.1}), 1.0, 1e-6);      // cell (7, 5)
  EXPECT_NEAR(map.at_world({-0.3, -0.3}), std::sqrt(0.5), 1e-6);  // cell (4, 4)
  EXPECT_DOUBLE_EQ(map.at_world({2.6, 0.0}), 4.0);
  EXPECT_DOUBLE_EQ(map.at_world({0.0, -2.51}), 4.0);
}

TEST(DistanceMap, RejectsNegativeMaxDistance) {
  EXPECT_THROW(DistanceMap(OccupancyGrid(2, 2, 1.0, {0, 0}), -1.0), std::invalid_argument);
}

}  // namespace distance_map_test
}  // namespace playerkit::grid
