#include "algorithms/grid/occupancy_grid_builder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace playerkit::grid {
namespace occupancy_grid_builder_test {

constexpr double kHalfSide = 3.02;  // walls at x, y = +-3.02: inside cells, not on borders
constexpr int kBeams = 720;
constexpr double kAngleMin = -std::numbers::pi;
constexpr double kIncrement = 2.0 * std::numbers::pi / kBeams;

double distance_to_square(const Eigen::Vector2d& from, double angle) {
  const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
  double best = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 2; ++axis) {
    if (direction[axis] == 0.0) continue;
    const double wall = direction[axis] > 0 ? kHalfSide : -kHalfSide;
    best = std::min(best, (wall - from[axis]) / direction[axis]);
  }
  return best;
}

// A perfect 360-degree scan of the room from `pose`, in the laser frame.
std::vector<double> scan_of_room(const geometry::Pose2& pose) {
  std::vector<double> ranges(kBeams);
  for (int i = 0; i < kBeams; ++i) {
    ranges[static_cast<std::size_t>(i)] =
        distance_to_square(pose.translation(), pose.yaw + kAngleMin + i * kIncrement);
  }
  return ranges;
}

OccupancyGrid map_of_room() {
  OccupancyGridBuilder builder;
  const geometry::Pose2 poses[] = {{0.0, 0.0, 0.0},   {1.5, 1.2, 0.7},  {-1.7, 1.1, 2.0},
                                   {-1.4, -1.6, -2.5}, {1.3, -1.5, -0.9}, {0.2, 2.2, 1.6},
                                   {-2.3, -0.1, 3.0},  {2.1, 0.3, -1.2}};
  for (const auto& pose : poses) builder.add_scan(pose, scan_of_room(pose), kAngleMin, kIncrement, 10.0);
  EXPECT_EQ(builder.scan_count(), std::size(poses));
  return builder.build();
}

TEST(OccupancyGridBuilder, RebuildsTheWallsOfASquareRoom) {
  const OccupancyGrid grid = map_of_room();
  const double resolution = 0.05;
  ASSERT_DOUBLE_EQ(grid.resolution(), resolution);

  // Bounds: the walls' cells plus a 1 m margin.
  EXPECT_NEAR(grid.origin().x(), -kHalfSide - 1.0, 1.5 * resolution);
  EXPECT_NEAR(grid.origin().y(), -kHalfSide - 1.0, 1.5 * resolution);
  EXPECT_NEAR(grid.width() * resolution, 2.0 * kHalfSide + 2.0, 2.5 * resolution);
  EXPECT_NEAR(grid.height() * resolution, 2.0 * kHalfSide + 2.0, 2.5 * resolution);

  // Every wall cell away from the corners is occupied.
  int wall_points = 0, occupied_wall_points = 0;
  for (double along = -2.9; along <= 2.9; along += resolution) {
    const Eigen::Vector2d points[] = {{kHalfSide, along}, {-kHalfSide, along},
                                      {along, kHalfSide}, {along, -kHalfSide}};
    for (const auto& point : points) {
      ++wall_points;
      occupied_wall_points += grid.state_at_world(point) == CellState::occupied;
    }
  }
  EXPECT_EQ(occupied_wall_points, wall_points);

  int interior = 0, interior_free = 0;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      const Eigen::Vector2d centre = grid.cell_centre({col, row});
      const double outward = std::max(std::abs(centre.x()), std::abs(centre.y())) - kHalfSide;
      const CellState state = grid.at(col, row);
      if (outward < -0.1) {
        ++interior;
        interior_free += state == CellState::free;
      } else if (outward > 0.05) {
        EXPECT_EQ(state, CellState::unknown) << "behind a wall: " << centre.transpose();
      }
      if (std::abs(outward) > 0.05) {
        EXPECT_NE(state, CellState::occupied) << centre.transpose();
      }
    }
  }
  EXPECT_EQ(interior_free, interior);
}

TEST(OccupancyGridBuilder, NoReturnReadingsCarryNoInformationByDefault) {
  OccupancyMappingParameters parameters;
  parameters.margin = 1.5;  // so that the unknown cells checked lie inside the grid
  OccupancyGridBuilder builder(parameters);
  std::vector<double> ranges(kBeams, 5.0);  // == max_range: nothing seen
  ranges[kBeams / 2] = 2.0;                 // straight ahead: a wall at 2 m
  for (int i = 0; i < 5; ++i) builder.add_scan({0.0, 0.0, 0.0}, ranges, kAngleMin, kIncrement, 5.0);
  const OccupancyGrid grid = builder.build();
  EXPECT_NEAR(grid.height() * 0.05, 3.0, 0.11);  // the margin around one beam's cells: nothing else was touched
  EXPECT_EQ(grid.state_at_world({2.0, 0.0}), CellState::occupied);
  EXPECT_EQ(grid.state_at_world({1.0, 0.0}), CellState::free);
  EXPECT_EQ(grid.state_at_world({0.0, 1.0}), CellState::unknown);   // to the left: a no-return beam
  EXPECT_EQ(grid.state_at_world({-0.1, -1.0}), CellState::unknown);  // to the right
}

TEST(OccupancyGridBuilder, NoReturnReadingsClearUpToTheirClearRange) {
  OccupancyMappingParameters parameters;
  parameters.margin = 0.0;
  parameters.no_return_clear_range = 3.0;
  OccupancyGridBuilder builder(parameters);
  const std::vector<double> ranges(kBeams, 5.0);
  for (int i = 0; i < 5; ++i) builder.add_scan({0.0, 0.0, 0.0}, ranges, kAngleMin, kIncrement, 5.0);
  const OccupancyGrid grid = builder.build();
  EXPECT_EQ(grid.state_at_world({0.0, 2.8}), CellState::free);
  EXPECT_EQ(grid.state_at_world({2.8, 0.0}), CellState::free);
  EXPECT_EQ(grid.state_at_world({0.0, 3.3}), CellState::unknown);
  for (const CellState state : grid.cells()) EXPECT_NE(state, CellState::occupied);
}

TEST(OccupancyGridBuilder, NoReturnReadingsClearButDoNotMark) {
  OccupancyMappingParameters parameters;
  parameters.margin = 0.0;
  parameters.no_return_clear_range = 100.0;  // beyond max_range: clears up to max_range
  OccupancyGridBuilder builder(parameters);
  const std::vector<double> ranges(kBeams, 5.0);  // == max_range: nothing seen
  for (int i = 0; i < 5; ++i) builder.add_scan({0.0, 0.0, 0.0}, ranges, kAngleMin, kIncrement, 5.0);
  const OccupancyGrid grid = builder.build();
  EXPECT_NEAR(grid.width() * 0.05, 10.0, 0.11);  // cleared out to the 5 m circle
  int free_cells = 0;
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      ASSERT_NE(grid.at(col, row), CellState::occupied);
      const double radius = grid.cell_centre({col, row}).norm();
      if (radius < 4.9) {
        EXPECT_EQ(grid.at(col, row), CellState::free) << radius;
      } else if (radius > 5.1) {
        EXPECT_EQ(grid.at(col, row), CellState::unknown) << radius;
      }
      free_cells += grid.at(col, row) == CellState::free;
    }
  }
  EXPECT_GT(free_cells, 0.95 * std::numbers::pi * 100 * 100);  // the disc of radius 100 cells
}

TEST(OccupancyGridBuilder, ReadingsBeyondTheUsableRangeOnlyClearUpToIt) {
  OccupancyMappingParameters parameters;
  parameters.max_usable_range = 2.0;
  parameters.margin = 0.0;
  OccupancyGridBuilder builder(parameters);
  const std::vector<double> ranges(kBeams, 4.0);  // a real return, but too far to trust
  for (int i = 0; i < 5; ++i) builder.add_scan({1.0, -1.0, 0.3}, ranges, kAngleMin, kIncrement, 8.0);
  const OccupancyGrid grid = builder.build();
  EXPECT_NEAR(grid.width() * 0.05, 4.0, 0.11);
  EXPECT_EQ(grid.state_at_world({1.0 + 1.5, -1.0}), CellState::free);
  EXPECT_EQ(grid.state_at_world({1.0, -1.0 - 1.5}), CellState::free);
  for (const CellState state : grid.cells()) EXPECT_NE(state, CellState::occupied);
}

TEST(OccupancyGridBuilder, OneHitMarksAndRepeatedMissesClear) {
  OccupancyMappingParameters parameters;
  parameters.margin = 0.0;
  OccupancyGridBuilder builder(parameters);
  const double ranges[] = {2.0};
  builder.add_scan({0.01, 0.01, 0.0}, ranges, 0.0, 0.0, 10.0);
  OccupancyGrid grid = builder.build();
  EXPECT_EQ(grid.state_at_world({2.02, 0.02}), CellState::occupied);  // p(0.85) = 0.70
  EXPECT_EQ(grid.state_at_world({1.0, 0.02}), CellState::unknown);    // p(-0.4) = 0.40

  // The obstacle goes away: beams now pass through its cell.
  const double longer[] = {3.0};
  for (int i = 0; i < 6; ++i) builder.add_scan({0.01, 0.01, 0.0}, longer, 0.0, 0.0, 10.0);
  grid = builder.build();
  EXPECT_EQ(grid.state_at_world({2.02, 0.02}), CellState::free);
  EXPECT_EQ(grid.state_at_world({3.02, 0.02}), CellState::occupied);
}

TEST(OccupancyGridBuilder, IgnoresInvalidReadingsAndRefusesToBuildFromNothing) {
  OccupancyGridBuilder builder;
  EXPECT_THROW((void)builder.build(), std::logic_error);
  const double ranges[] = {std::numeric_limits<double>::quiet_NaN(), 0.0, -1.0};
  builder.add_scan({}, ranges, 0.0, 0.1, 10.0);
  EXPECT_EQ(builder.scan_count(), 1u);
  EXPECT_THROW((void)builder.build(), std::logic_error);
}

TEST(OccupancyGridBuilder, AResolutionTooFineIsRefusedNamingOneThatFits) {
  // Ten beams reaching 5 m ahead: at 0.1 mm a cell, 50,000 cells across.
  const std::vector<double> ranges(10, 5.0);
  OccupancyMappingParameters fine;
  fine.resolution = 0.0001;
  OccupancyGridBuilder builder(fine);
  std::string message;
  try {
    builder.add_scan({0.0, 0.0, 0.0}, ranges, -0.5, 0.1, 30.0);
    FAIL() << "no error";
  } catch (const GridTooLarge& error) {
    message = error.what();
  }
  EXPECT_EQ(message.rfind("a map of ", 0), 0u) << message;
  EXPECT_NE(message.find(" is more than the limit of 50 million at a resolution of 0.0001 m (the area seen so far, "),
            std::string::npos)
      << message;
  // The resolution it suggests takes the same scan.
  const auto at = message.find(" fits at ");
  ASSERT_NE(at, std::string::npos) << message;
  OccupancyMappingParameters suggested;
  suggested.resolution = std::stod(message.substr(at + 9));
  EXPECT_GT(suggested.resolution, fine.resolution);
  EXPECT_LT(suggested.resolution, 0.01);
  OccupancyGridBuilder coarser(suggested);
  coarser.add_scan({0.0, 0.0, 0.0}, ranges, -0.5, 0.1, 30.0);
  EXPECT_LE(static_cast<std::int64_t>(coarser.build().cells().size()), kMaxGridCells);
}

TEST(OccupancyGridBuilder, GrowsIntoNegativeAndFarCoordinates) {
  OccupancyMappingParameters parameters;
  parameters.margin = 0.5;
  parameters.resolution = 0.2;  // 900 m x 500 m: 11 million cells (at 5 cm, over kMaxGridCells)
  OccupancyGridBuilder builder(parameters);
  const double ranges[] = {1.0};
  builder.add_scan({-500.0, -300.0, 0.0}, ranges, 0.0, 0.0, 10.0);
  builder.add_scan({400.0, 200.0, std::numbers::pi / 2}, ranges, 0.0, 0.0, 10.0);
  const OccupancyGrid grid = builder.build();
  EXPECT_EQ(grid.state_at_world({-499.0 + 0.01, -300.0 + 0.01}), CellState::occupied);
  EXPECT_EQ(grid.state_at_world({400.0 + 0.01, 201.0 + 0.01}), CellState::occupied);
  EXPECT_NEAR(grid.origin().x(), -500.5, 0.201);
  EXPECT_NEAR(grid.origin().y(), -300.5, 0.201);
}

TEST(OccupancyGridBuilder, RejectsBadParameters) {
  EXPECT_THROW(OccupancyGridBuilder({.resolution = 0.0}), std::invalid_argument);
  EXPECT_THROW(OccupancyGridBuilder({.max_usable_range = -1.0}), std::invalid_argument);
  EXPECT_THROW(OccupancyGridBuilder({.no_return_clear_range = -1.0}), std::invalid_argument);
  EXPECT_THROW(OccupancyGridBuilder({.no_return_clear_range = std::nan("")}), std::invalid_argument);
  EXPECT_THROW(OccupancyGridBuilder({.occupied_probability = 1.0}), std::invalid_argument);
  EXPECT_THROW(OccupancyGridBuilder({.margin = -0.1}), std::invalid_argument);
}

}  // namespace occupancy_grid_builder_test
}  // namespace playerkit::grid
