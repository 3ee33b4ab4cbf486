#include "emulators/mobile_base/obstacle_search.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::emulators::mobile_base {

std::optional<NearestObstacle> nearest_obstacle(const grid::OccupancyGrid& map,
                                                const Eigen::Vector2d& centre, double radius) {
  if (map.empty() || !(radius > 0.0) || !centre.allFinite()) return std::nullopt;
  const double resolution = map.resolution();
  const Eigen::Vector2i low = map.world_to_cell(centre - Eigen::Vector2d(radius, radius));
  const Eigen::Vector2i high = map.world_to_cell(centre + Eigen::Vector2d(radius, radius));
  const int col_begin = std::max(low.x(), 0), col_end = std::min(high.x(), map.width() - 1);
  const int row_begin = std::max(low.y(), 0), row_end = std::min(high.y(), map.height() - 1);
  std::optional<NearestObstacle> best;
  for (int row = row_begin; row <= row_end; ++row) {
    for (int col = col_begin; col <= col_end; ++col) {
      if (map.at(col, row) != grid::CellState::occupied) continue;
      const Eigen::Vector2d corner = map.origin() + resolution * Eigen::Vector2d(static_cast<double>(col), static_cast<double>(row));
      const Eigen::Vector2d point =
          centre.cwiseMax(corner).cwiseMin(corner + Eigen::Vector2d(resolution, resolution));
      const double distance = (point - centre).norm();
      if (distance < radius && (!best || distance < best->distance)) {
        best = NearestObstacle{distance, point};
      }
    }
  }
  return best;
}

}  // namespace playerkit::emulators::mobile_base
