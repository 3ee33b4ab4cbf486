#include "algorithms/grid/range_caster.hpp"

#include "algorithms/grid/distance_map.hpp"
#include "algorithms/grid/grid_traversal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace playerkit::grid {
namespace {

// Lengths below are in cells. Every point of a cell is within sqrt(2)/2 of
// its centre, so if the centres of p's cell and of the nearest stopping cell
// are d apart, nothing closer to p than d - sqrt(2) is in a stopping cell.
// The extra 0.086 absorbs rounding in p.
constexpr double kJumpMargin = 1.5;
// Jump only from cells at least this clear, i.e. by at least 1.5 cells:
// shorter jumps cost more in lookups than walking the cells.
constexpr int kClearanceToJump = 3;
// A walk that reaches a cell this clear goes back to jumping (rays grazing
// a long wall would otherwise walk all of it). The point it resumes from
// lies on that cell's border, so rounding may put it in the neighbour
// before, one cell less clear: that must still be enough to jump from, or
// the walk would restart where it was.
constexpr int kClearanceToResumeJumping = 4;
static_assert(kClearanceToResumeJumping - 1 >= kClearanceToJump);
// Clearances are stored in a byte per cell (small maps then stay in cache).
constexpr int kLargestClearance = 255;

// Cell walks started from different points accumulate different rounding,
// so near a corner (where the ray crosses both axes almost at once) two
// walks of one ray may step through different neighbours. Their crossing
// times differ by roughly (ray length in cells)^2 * 1e-16 cells, far below
// this up to rays of 10^4 cells.
constexpr double kCornerTolerance = 1e-6;  // cells

// `crossing` is where the walk enters `cell`, so it lies on the cell's
// border; near a corner both of its coordinates are near the cell's bounds.
bool enters_near_a_corner(const Eigen::Vector2i& cell, const Eigen::Vector2d& crossing) {
  const auto near_a_bound = [](double coordinate, int low) {
    const double inside = coordinate - low;
    return std::abs(inside) < kCornerTolerance || std::abs(inside - 1.0) < kCornerTolerance;
  };
  return near_a_bound(crossing.x(), cell.x()) && near_a_bound(crossing.y(), cell.y());
}

DistanceTo distance_sources(RayStop stop) {
  return stop == RayStop::occupied ? DistanceTo::occupied : DistanceTo::occupied_or_unknown;
}

}  // namespace

RangeCaster::RangeCaster(const OccupancyGrid& grid, RayStop stop, double max_jump)
    : stop_(stop),
      width_(grid.width()),
      height_(grid.height()),
      resolution_(grid.resolution()),
      origin_(grid.origin()) {
  // A zero cap would read 0 everywhere and so make every cell look stopping.
  if (!(max_jump > 0.0)) throw std::invalid_argument("RangeCaster: max_jump must be positive");
  if (grid.empty()) return;
  const double cap = std::min(max_jump, kLargestClearance * resolution_);
  const DistanceMap distances(grid, cap, distance_sources(stop));
  clearance_.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  for (int row = 0; row < height_; ++row) {
    for (int col = 0; col < width_; ++col) {
      const double metres = distances.at(col, row);
      // Rounded down, so never more than the truth; the 1e-6 only undoes
      // float rounding of whole-cell distances (3 cells read as 2.9999999).
      const double cells = std::floor(metres / resolution_ + 1e-6);
      clearance_[index(col, row)] =
          metres == 0.0 ? 0 : static_cast<std::uint8_t>(std::clamp(cells, 1.0, double(kLargestClearance)));
    }
  }
}

double RangeCaster::range(const Eigen::Vector2d& origin, double angle, double max_range) const {
  if (width_ == 0 || !(max_range > 0.0)) return max_range;
  // The same segment, computed the same way, as cast_ray walks.
  const Eigen::Vector2d from = (origin - origin_) / resolution_;
  const double length = max_range / resolution_;
  const Eigen::Vector2d to = from + length * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  const Eigen::Vector2d unit = (to - from) / length;  // one cell along the ray
  const auto in_grid = [this](int col, int row) {
    return col >= 0 && row >= 0 && col < width_ && row < height_;
  };

  double travelled = 0.0;  // cells of the ray known to cross no stopping cell
  for (;;) {
    const Eigen::Vector2d point = from + travelled * unit;
    // The grid is convex: a ray that has left it never comes back, and
    // cast_ray reports leaving as max_range.
    if (!(point.x() >= 0.0 && point.y() >= 0.0 && point.x() < width_ && point.y() < height_)) {
      return max_range;
    }
    const int clearance = clearance_[index(static_cast<int>(point.x()), static_cast<int>(point.y()))];
    if (clearance >= kClearanceToJump) {
      travelled += clearance - kJumpMargin;
      if (travelled >= length) return max_range;
      continue;
    }

    // Entry times in this walk are fractions of what is left of the segment;
    // from the origin (start == 0) they are cast_ray's own, bit for bit.
    const double start = travelled / length;
    double range = max_range;
    bool resume_jumping = false;
    bool through_a_corner = false;
    bool first_cell = true;
    detail::traverse_segment(point, to, [&](const Eigen::Vector2i& cell, double entry) {
      // Before anything else: the corner may also be where the ray leaves the grid.
      if (!first_cell && enters_near_a_corner(cell, point + entry * (to - point))) {
        through_a_corner = true;
        return false;
      }
      first_cell = false;
      if (!in_grid(cell.x(), cell.y())) return false;  // left the grid: max_range
      const int cell_clearance = clearance_[index(cell.x(), cell.y())];
      if (cell_clearance == 0) {  // a stopping cell
        range = (start + entry * (1.0 - start)) * max_range;
        return false;
      }
      if (cell_clearance >= kClearanceToResumeJumping) {
        travelled = (start + entry * (1.0 - start)) * length;
        resume_jumping = true;
        return false;
      }
      return true;
    });
    if (through_a_corner) break;
    if (!resume_jumping) return range;
    if (travelled >= length) return max_range;
  }

  // The ray grazes a cell corner, so which of the two cells beside it the
  // walk visits is decided by rounding; walking the whole ray as cast_ray
  // does makes the same choice it makes.
  double range = max_range;
  detail::traverse_segment(from, to, [&](const Eigen::Vector2i& cell, double entry) {
    if (!in_grid(cell.x(), cell.y())) return false;
    if (clearance_[index(cell.x(), cell.y())] == 0) {
      range = entry * max_range;
      return false;
    }
    return true;
  });
  return range;
}

}  // namespace playerkit::grid
