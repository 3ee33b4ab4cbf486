#pragma once
// For the tests: a 3 m x 3 m room of 5 cm cells whose walls are the border
// cells, and the distances in it computed by hand (no grid code), to check
// the emulator's ray casting against.

#include "algorithms/grid/occupancy_grid.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace playerkit::emulators::testing {

inline constexpr double kRoomCell = 0.05;
inline constexpr int kRoomCells = 60;
// The walls' inner faces.
inline constexpr double kRoomLow = kRoomCell;
inline constexpr double kRoomHigh = kRoomCell * (kRoomCells - 1);

inline grid::OccupancyGrid box_room() {
  grid::OccupancyGrid room(kRoomCells, kRoomCells, kRoomCell, Eigen::Vector2d::Zero(),
                           grid::CellState::free);
  for (int i = 0; i < kRoomCells; ++i) {
    room.set(i, 0, grid::CellState::occupied);
    room.set(i, kRoomCells - 1, grid::CellState::occupied);
    room.set(0, i, grid::CellState::occupied);
    room.set(kRoomCells - 1, i, grid::CellState::occupied);
  }
  return room;
}

// Distance from a point inside the room to the wall along `angle` (world).
inline double room_range(const Eigen::Vector2d& origin, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  double range = std::numeric_limits<double>::infinity();
  if (c > 1e-12) range = std::min(range, (kRoomHigh - origin.x()) / c);
  if (c < -1e-12) range = std::min(range, (kRoomLow - origin.x()) / c);
  if (s > 1e-12) range = std::min(range, (kRoomHigh - origin.y()) / s);
  if (s < -1e-12) range = std::min(range, (kRoomLow - origin.y()) / s);
  return range;
}

}  // namespace playerkit::emulators::testing
