#pragma once
// Internal: the cells a segment crosses, in order, after Amanatides & Woo
// (1987), "A Fast Voxel Traversal Algorithm for Ray Tracing". Shared by
// ray_cast.cpp, occupancy_grid_builder.cpp and wavefront/clearance_map.cpp
// (which needs it without an OccupancyGrid); use ray_cast.hpp outside.

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>

namespace playerkit::grid::detail {

// Floor of a cell coordinate, clamped so absurd inputs cannot overflow int.
inline int cell_index(double cells) {
  constexpr double limit = 1.0e9;
  if (!(cells > -limit)) return -static_cast<int>(limit);
  if (!(cells < limit)) return static_cast<int>(limit);
  return static_cast<int>(std::floor(cells));
}

// `from` and `to` are in cell units (cell (i, j) spans [i, i+1) x [j, j+1)).
// Calls visit(cell, t) for every cell from from's to to's, where t in [0, 1]
// is the fraction of the segment at which it enters the cell (0 for the
// first). Consecutive cells differ in exactly one coordinate by one: when the
// segment passes exactly through a corner, the x neighbour is visited first.
// Stops early when visit returns false.
template <typename Visitor>
void traverse_segment(const Eigen::Vector2d& from, const Eigen::Vector2d& to, Visitor&& visit) {
  Eigen::Vector2i cell(cell_index(from.x()), cell_index(from.y()));
  const Eigen::Vector2i last(cell_index(to.x()), cell_index(to.y()));
  const Eigen::Vector2d direction = to - from;

  constexpr double infinity = std::numeric_limits<double>::infinity();
  Eigen::Vector2i step;
  Eigen::Vector2d next_crossing;  // t at which the segment next crosses a cell border, per axis
  Eigen::Vector2d crossing_interval;
  for (int axis = 0; axis < 2; ++axis) {
    if (direction[axis] > 0.0) {
      step[axis] = 1;
      next_crossing[axis] = (cell[axis] + 1.0 - from[axis]) / direction[axis];
      crossing_interval[axis] = 1.0 / direction[axis];
    } else if (direction[axis] < 0.0) {
      step[axis] = -1;
      next_crossing[axis] = (from[axis] - cell[axis]) / -direction[axis];
      crossing_interval[axis] = -1.0 / direction[axis];
    } else {
      step[axis] = 0;
      next_crossing[axis] = infinity;
      crossing_interval[axis] = infinity;
    }
  }

  // Count the steps from the end cells rather than trusting the t values, so
  // rounding can neither overshoot the last cell nor loop forever.
  std::int64_t x_steps_left = std::llabs(static_cast<long long>(last.x()) - cell.x());
  std::int64_t y_steps_left = std::llabs(static_cast<long long>(last.y()) - cell.y());
  if (!visit(static_cast<const Eigen::Vector2i&>(cell), 0.0)) return;
  while (x_steps_left > 0 || y_steps_left > 0) {
    const bool step_x =
        y_steps_left == 0 || (x_steps_left > 0 && next_crossing.x() <= next_crossing.y());
    const int axis = step_x ? 0 : 1;
    // A zero direction component with steps left can only come from rounding.
    if (step[axis] == 0) step[axis] = (axis == 0 ? last.x() > cell.x() : last.y() > cell.y()) ? 1 : -1;
    cell[axis] += step[axis];
    const double entry = std::min(std::max(next_crossing[axis], 0.0), 1.0);
    next_crossing[axis] += crossing_interval[axis];
    (step_x ? x_steps_left : y_steps_left) -= 1;
    if (!visit(static_cast<const Eigen::Vector2i&>(cell), entry)) return;
  }
}

}  // namespace playerkit::grid::detail
