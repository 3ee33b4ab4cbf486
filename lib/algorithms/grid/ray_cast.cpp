#include "algorithms/grid/ray_cast.hpp"

#include "algorithms/grid/grid_traversal.hpp"

#include <cmath>

namespace playerkit::grid {
namespace {

Eigen::Vector2d to_cell_units(const OccupancyGrid& grid, const Eigen::Vector2d& point) {
  return (point - grid.origin()) / grid.resolution();
}

bool stops(CellState state, RayStop stop) {
  return stop == RayStop::occupied ? state == CellState::occupied : state != CellState::free;
}

}  // namespace

double cast_ray(const OccupancyGrid& grid, const Eigen::Vector2d& origin, double angle,
                double max_range, RayStop stop) {
  if (grid.empty() || !(max_range > 0.0)) return max_range;
  const Eigen::Vector2d from = to_cell_units(grid, origin);
  const Eigen::Vector2d to =
      from + (max_range / grid.resolution()) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  double range = max_range;
  detail::traverse_segment(from, to, [&](const Eigen::Vector2i& cell, double entry) {
    // Leaving the map is "nothing seen", as in Player's map_calc_range.
    if (!grid.contains(cell)) return false;
    if (stops(grid.at(cell), stop)) {
      range = entry * max_range;
      return false;
    }
    return true;
  });
  return range;
}

void trace_cells(const OccupancyGrid& grid, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                 const std::function<bool(const Eigen::Vector2i&)>& visit) {
  if (!(grid.resolution() > 0.0)) return;  // a default-constructed grid has no cells to name
  detail::traverse_segment(to_cell_units(grid, from), to_cell_units(grid, to),
                           [&](const Eigen::Vector2i& cell, double) { return visit(cell); });
}

}  // namespace playerkit::grid
