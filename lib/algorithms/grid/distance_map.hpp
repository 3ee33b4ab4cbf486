#pragma once
// Distance from every cell to the nearest occupied cell (or, on request, the
// nearest cell that is not free), for the likelihood field laser model and
// for ray marching. Exact Euclidean distance transform in O(cells).

#include "algorithms/grid/occupancy_grid.hpp"

#include <cstddef>
#include <vector>

namespace playerkit::grid {

// Which cells distances are measured to.
enum class DistanceTo {
  occupied,             // the likelihood field: only obstacles
  occupied_or_unknown,  // everything that is not free, i.e. what stops RayStop::occupied_or_unknown
};

class DistanceMap {
 public:
  DistanceMap() = default;
  // Distances are in metres and capped at `max_distance`; a map with no
  // source cell is max_distance everywhere. A source cell itself reads 0
  // and every other cell min(one cell width, max_distance) or more.
  DistanceMap(const OccupancyGrid& grid, double max_distance,
              DistanceTo sources = DistanceTo::occupied);

  double max_distance() const { return max_distance_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // Unchecked; inline because ray marching reads it in its inner loop.
  double at(int col, int row) const {
    return distances_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
                      static_cast<std::size_t>(col)];
  }
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
