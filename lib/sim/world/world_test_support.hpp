#pragma once
// For the world's tests only: floors with walls, robots to put on them, and
// a shape test of their own (not body_geometry's) for independent checks.

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <utility>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "sim/world/model_spec.hpp"
#include "sim/world/world.hpp"

namespace playerkit::sim::world_test_support {

inline constexpr double kFloorCell = 0.05;  // m

// A free floor `metres` wide centred on the origin, no walls.
inline grid::OccupancyGrid open_floor(double metres = 20.0) {
  const int cells = static_cast<int>(std::lround(metres / kFloorCell));
  return grid::OccupancyGrid::centred(cells, cells, kFloorCell, grid::CellState::free);
}

// Marks occupied every cell that overlaps [x0, x1] x [y0, y1] (cells are
// kFloorCell wide, so walls on multiples of it fill exactly that).
inline void fill_walls(grid::OccupancyGrid& map, double x0, double y0, double x1, double y1) {
  const double eps = 1e-9;
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      const Eigen::Vector2d low = map.origin() + map.resolution() * Eigen::Vector2d(col, row);
      const Eigen::Vector2d high = low + Eigen::Vector2d::Constant(map.resolution());
      if (high.x() > x0 + eps && low.x() < x1 - eps && high.y() > y0 + eps && low.y() < y1 - eps) {
        map.set(col, row, grid::CellState::occupied);
      }
    }
  }
}

// open_floor() with a wall from x = 2.05 to 2.5 across it.
inline grid::OccupancyGrid walled_floor() {
  grid::OccupancyGrid map = open_floor();
  fill_walls(map, 2.05, -10.0, 2.5, 10.0);
  return map;
}

// A differential robot with a 0.4 x 0.4 m body.
inline ModelSpec robot(const std::string& name, const geometry::Pose2& pose, PositionSpec position = {}) {
  ModelSpec spec;
  spec.name = name;
  spec.type = "position";
  spec.pose = pose;
  spec.body.size = {0.4, 0.4};
  spec.params = std::move(position);
  return spec;
}

// Any model: `params` say what it is; the body keeps ModelSpec's defaults.
inline ModelSpec model(const std::string& name, ModelId parent, const geometry::Pose2& pose, ModelParams params) {
  ModelSpec spec;
  spec.name = name;
  spec.parent = parent;
  spec.pose = pose;
  spec.params = std::move(params);
  return spec;
}

// A sensor or device riding on `parent` at `pose`, without a body of its own.
inline ModelSpec mounted(ModelId parent, ModelParams params, const geometry::Pose2& pose = {}) {
  ModelSpec spec;
  spec.parent = parent;
  spec.pose = pose;
  spec.body.present = false;
  spec.params = std::move(params);
  return spec;
}

// An object (box, puck) with a body at `pose`.
inline ModelSpec object(const std::string& name, const geometry::Pose2& pose, Shape shape, double size_x,
                        double size_y) {
  ModelSpec spec;
  spec.name = name;
  spec.type = "box";
  spec.pose = pose;
  spec.body.shape = shape;
  spec.body.size = {size_x, size_y};
  return spec;
}

inline void run(World& world, int steps) {
  for (int i = 0; i < steps; ++i) world.step();
}

}  // namespace playerkit::sim::world_test_support
