#include "algorithms/grid/occupancy_grid.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace playerkit::grid {

OccupancyGrid::OccupancyGrid(int width, int height, double resolution, Eigen::Vector2d origin,
                             CellState fill)
    : width_(width), height_(height), resolution_(resolution), origin_(origin) {
  if (width <= 0 || height <= 0) {
    throw std::invalid_argument("OccupancyGrid: width and height must be positive");
  }
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw std::invalid_argument("OccupancyGrid: resolution must be positive and finite");
  }
  if (static_cast<std::int64_t>(width) * height > kMaxGridCells) {
    throw GridTooLarge(width, height, too_many_cells_message(width, height));
  }
  cells_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill);
}

std::string too_many_cells_message(std::int64_t width, std::int64_t height) {
  const double millions = static_cast<double>(width) * static_cast<double>(height) / 1e6;
  char figure[32];
  std::snprintf(figure, sizeof figure, millions < 10 ? "%.1f" : "%.0f", millions);
  return "a map of " + std::to_string(width) + " x " + std::to_string(height) + " cells (" + figure +
         " million) is more than the limit of " + std::to_string(kMaxGridCells / 1'000'000) + " million";
}

OccupancyGrid OccupancyGrid::centred(int width, int height, double resolution, CellState fill) {
  const Eigen::Vector2d half_extent(0.5 * width * resolution, 0.5 * height * resolution);
  return OccupancyGrid(width, height, resolution, -half_extent, fill);
}

CellState OccupancyGrid::state_at_world(const Eigen::Vector2d& point) const {
  const Eigen::Vector2i cell = world_to_cell(point);
  return contains(cell) ? at(cell) : CellState::unknown;
}

Eigen::Vector2i OccupancyGrid::world_to_cell(const Eigen::Vector2d& point) const {
  return cell_containing(point, origin_, resolution_);
}

Eigen::Vector2d OccupancyGrid::cell_centre(const Eigen::Vector2i& cell) const {
  return origin_ + (cell.cast<double>() + Eigen::Vector2d::Constant(0.5)) * resolution_;
}

}  // namespace playerkit::grid
