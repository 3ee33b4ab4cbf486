#pragma once
// A 2-D occupancy grid in world coordinates. Row-major, row 0 at the lowest
// y (the ROS convention); image loaders flip rows, since images start at the
// top. Cell states use Player's map convention: -1 free, 0 unknown, +1
// occupied.

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace playerkit::grid {

// The most cells a grid may have: 50 million, a 7071-cell square (350 m at
// 5 cm, 70 m at 1 cm; the largest Radish maps are 2 million cells at 5 cm).
// Memory grows with cells: 1 byte here, and localizing on the map adds about
// 24 more at worst (4 for the distance map, 4 for the likelihood table, 16
// per free cell for uniform sampling), so 1.2 GB at the limit; building a map
// from scans takes about 6 (4 of log odds, 1 of scan marks, 1 for the grid).
// Without it `amcl-offline map --resolution 0.0001` reached 6 GB.
inline constexpr std::int64_t kMaxGridCells = 50'000'000;

// A grid of more than kMaxGridCells cells was asked for. what() gives its size
// (and, from a map builder, the resolution at which the area would fit).
class GridTooLarge : public std::length_error {
 public:
  GridTooLarge(std::int64_t width, std::int64_t height, const std::string& message)
      : std::length_error(message), width_(width), height_(height) {}
  [[nodiscard]] std::int64_t width() const { return width_; }
  [[nodiscard]] std::int64_t height() const { return height_; }

 private:
  std::int64_t width_;
  std::int64_t height_;
};

// The cell holding `point` on a grid of this origin and resolution. Clamps
// before converting: a far-away or non-finite point must not overflow int.
inline Eigen::Vector2i cell_containing(const Eigen::Vector2d& point, const Eigen::Vector2d& origin,
                                       double resolution) {
  const auto to_index = [](double cells) {
    constexpr double limit = 1.0e9;
    if (!(cells > -limit)) return static_cast<int>(-limit);
    if (!(cells < limit)) return static_cast<int>(limit);
    return static_cast<int>(std::floor(cells));
  };
  const Eigen::Vector2d cells = (point - origin) / resolution;
  return {to_index(cells.x()), to_index(cells.y())};
}

// "a map of W x H cells (N million) is more than the limit of 50 million"
std::string too_many_cells_message(std::int64_t width, std::int64_t height);

enum class CellState : std::int8_t { free = -1, unknown = 0, occupied = 1 };

class OccupancyGrid {
 public:
  OccupancyGrid() = default;
  // `origin` is the world position of the outer corner of cell (0, 0), the
  // corner with the lowest x and y. Throws std::invalid_argument for a
  // non-positive size or resolution, GridTooLarge over kMaxGridCells.
  OccupancyGrid(int width, int height, double resolution, Eigen::Vector2d origin,
                CellState fill = CellState::unknown);

  // Player 1.5 places the map's centre at the world origin (manual 7.3).
  static OccupancyGrid centred(int width, int height, double resolution,
                               CellState fill = CellState::unknown);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  bool empty() const { return cells_.empty(); }

  bool contains(int col, int row) const {
    return col >= 0 && row >= 0 && col < width_ && row < height_;
  }
  bool contains(const Eigen::Vector2i& cell) const { return contains(cell.x(), cell.y()); }

  // Unchecked access; call contains() first for untrusted indices.
  CellState at(int col, int row) const { return cells_[index(col, row)]; }
  CellState at(const Eigen::Vector2i& cell) const { return at(cell.x(), cell.y()); }
  void set(int col, int row, CellState state) { cells_[index(col, row)] = state; }

  // Cells outside the grid read as unknown.
  CellState state_at_world(const Eigen::Vector2d& point) const;

  // The cell holding a world point (floor), which may lie outside the grid.
  Eigen::Vector2i world_to_cell(const Eigen::Vector2d& point) const;
  Eigen::Vector2d cell_centre(const Eigen::Vector2i& cell) const;

  std::span<const CellState> cells() const { return cells_; }
  std::span<CellState> cells() { return cells_; }

  std::size_t index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(col);
  }

 private:
  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.0;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  std::vector<CellState> cells_;
};

}  // namespace playerkit::grid
