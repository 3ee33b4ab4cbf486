#pragma once
// How far a robot's centre is from everything it must keep away from: every
// occupied or unknown cell, and everything outside the grid (unknown too).
// Cells are squares, not points: the clearance of a point is its Euclidean
// distance to the nearest point of any such square, which is what a round
// robot touching a wall measures.
//
//   ClearanceMap clearance(grid, 0.5);        // exact up to 0.5 m, once per map
//   clearance.at(col, row);                   // from a cell centre, metres
//   clearance.segment_clearance(a, b, 0.3);   // from a whole segment, exact up to 0.3 m
//
// Per cell the map holds four times the squared distance in cell units,
// which for a cell centre and a square is always a whole number (offsets
// are whole and half cells), so the comparisons a planner makes against it
// are exact. Built by a windowed two-pass transform, O(cells x max_distance
// in cells); segment and point queries are exact, using the map only to skip
// cells that are clearly far from everything.

#include <Eigen/Core>

#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"

namespace playerkit::wavefront {

class ClearanceMap {
 public:
  ClearanceMap() = default;
  // Distances up to `max_distance` metres are exact; farther ones read as at
  // least that. Throws std::invalid_argument for an empty grid or a
  // max_distance that is negative or more than 4096 cells.
  ClearanceMap(const grid::OccupancyGrid& grid, double max_distance);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  // The exact range, in whole cells (max_distance rounded up).
  int reach_cells() const { return reach_cells_; }
  double reach() const { return reach_cells_ * resolution_; }

  bool contains(int col, int row) const { return col >= 0 && row >= 0 && col < width_ && row < height_; }
  // Outside the grid reads as unknown.
  grid::CellState state(int col, int row) const {
    return contains(col, row) ? states_[index(col, row)] : grid::CellState::unknown;
  }
  // Occupied, unknown, or outside the grid.
  bool is_obstacle(int col, int row) const {
    return !contains(col, row) || states_[index(col, row)] != grid::CellState::free;
  }

  // 4 x (distance in cells)^2 from the centre of an in-grid cell, capped at
  // 4 x reach_cells()^2. Unchecked.
  float quarter_squared(int col, int row) const { return quarter_squared_[index(col, row)]; }
  // The same in metres (at most reach()).
  double at(int col, int row) const;

  // The cell holding a world point (floor; may be outside the grid).
  Eigen::Vector2i cell_of(const Eigen::Vector2d& point) const;
  Eigen::Vector2d cell_centre(int col, int row) const;

  // Exact distances in metres, capped at `limit` (the answer is min(true
  // distance, limit)); 0 when the point or segment touches an obstacle.
  // Any limit works; above reach() they cost more.
  double point_clearance(const Eigen::Vector2d& point, double limit) const;
  double segment_clearance(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double limit) const;
  double polyline_clearance(std::span<const Eigen::Vector2d> points, double limit) const;
  // segment_clearance(from, to, required) >= required, up to a nanometre of
  // rounding; stops at the first obstacle that is too close.
  bool segment_keeps(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double required) const;

  std::size_t index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col);
  }

 private:
  // Lowers `best` (metres) to the distance from the segment to any obstacle
  // square near cell (col, row) that is closer; returns false as soon as
  // best drops below `stop_below`.
  bool scan_around(int col, int row, const Eigen::Vector2d& from, const Eigen::Vector2d& to, double& best,
                   double stop_below) const;
  double segment_search(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double limit,
                        double stop_below) const;

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.0;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  int reach_cells_ = 0;
  std::vector<grid::CellState> states_;
  std::vector<float> quarter_squared_;
};

// Nanometres: how much rounding the clearance comparisons forgive.
inline constexpr double kClearanceTolerance = 1e-9;

}  // namespace playerkit::wavefront
