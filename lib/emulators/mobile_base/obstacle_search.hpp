#pragma once
// The occupied cell nearest to a point, within a radius: what a round robot
// of that radius would touch. Only occupied cells count; unknown cells and
// everything outside the grid are open space to an emulated robot.

#include "algorithms/grid/occupancy_grid.hpp"

#include <Eigen/Core>

#include <optional>

namespace playerkit::emulators::mobile_base {

struct NearestObstacle {
  double distance = 0.0;   // metres from the centre to the cell's nearest point
  Eigen::Vector2d point;   // that point, world frame
};

// Nothing when no occupied cell comes closer than `radius` to `centre`.
std::optional<NearestObstacle> nearest_obstacle(const grid::OccupancyGrid& map,
                                                const Eigen::Vector2d& centre, double radius);

}  // namespace playerkit::emulators::mobile_base
