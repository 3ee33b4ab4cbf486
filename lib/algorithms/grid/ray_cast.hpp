#pragma once
// Ray casting through an occupancy grid: the range a perfect laser would
// read, for the beam model and for map building.

#include "algorithms/grid/occupancy_grid.hpp"

#include <functional>

namespace playerkit::grid {

enum class RayStop {
  occupied,              // only occupied cells stop the ray
  occupied_or_unknown,   // Player 1.5's map_calc_range: anything not free
};

// Distance from `origin` along `angle` (world frame, radians) to the first
// stopping cell, or `max_range` if none is met within it or the ray leaves
// the grid.
double cast_ray(const OccupancyGrid& grid, const Eigen::Vector2d& origin, double angle,
                double max_range, RayStop stop = RayStop::occupied_or_unknown);

// Visits every cell a segment passes through, in order from `from` to `to`
// (both endpoints' cells included), including cells outside the grid. The
// visitor returns false to stop early.
void trace_cells(const OccupancyGrid& grid, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                 const std::function<bool(const Eigen::Vector2i&)>& visit);

}  // namespace playerkit::grid
