#pragma once
// Distance from every cell to the nearest occupied cell, for the likelihood
// field laser model. Exact Euclidean distance transform in O(cells).

#include "algorithms/grid/occupancy_grid.hpp"

#include <vector>

namespace playerkit::grid {

class DistanceMap {
 public:
  DistanceMap() = default;
  // Distances are in metres and capped at `max_distance`; a map with no
  // occupied cell is max_distance everywhere.
  DistanceMap(const OccupancyGrid& grid, double max_distance);

  double max_distance() const { return max_distance_; }
  int width() const { return width_; }
  int height() const { return height_; }

  double at(int col, int row) const;  // unchecked
  // Points outside the grid are max_distance away.
  double at_world(const Eigen::Vector2d& point) const;

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.0;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double max_distance_ = 0.0;
  std::vector<float> distances_;
};

}  // namespace playerkit::grid
