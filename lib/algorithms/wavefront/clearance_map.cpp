#include "algorithms/wavefront/clearance_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "algorithms/grid/grid_traversal.hpp"

namespace playerkit::wavefront {
namespace {

constexpr double kHalfDiagonal = 0.70710678118654757;  // of a cell, in cells
constexpr int kMaxReachCells = 4096;                     // keeps 4 x reach^2 exact in a float

// Squared distance from a point to an axis-aligned box.
double point_box_squared(const Eigen::Vector2d& p, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
  const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
  return dx * dx + dy * dy;
}

double point_segment_squared(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length_squared = ab.squaredNorm();
  double t = length_squared > 0.0 ? (p - a).dot(ab) / length_squared : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * ab - p).squaredNorm();
}

// Liang & Barsky's clip: does the segment meet the closed box?
bool segment_meets_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& lo,
                       const Eigen::Vector2d& hi) {
  double enter = 0.0, leave = 1.0;
  const Eigen::Vector2d d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    const double p[2] = {-d[axis], d[axis]};
    const double q[2] = {a[axis] - lo[axis], hi[axis] - a[axis]};
    for (int side = 0; side < 2; ++side) {
      if (p[side] == 0.0) {
        if (q[side] < 0.0) return false;
        continue;
      }
      const double t = q[side] / p[side];
      if (p[side] < 0.0) {
        enter = std::max(enter, t);
      } else {
        leave = std::min(leave, t);
      }
      if (enter > leave) return false;
    }
  }
  return true;
}

// Two convex shapes that do not meet are closest at a vertex of one of them.
double segment_box_distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& lo,
                            const Eigen::Vector2d& hi) {
  if (segment_meets_box(a, b, lo, hi)) return 0.0;
  double best = std::min(point_box_squared(a, lo, hi), point_box_squared(b, lo, hi));
  best = std::min(best, point_segment_squared(lo, a, b));
  best = std::min(best, point_segment_squared(hi, a, b));
  best = std::min(best, point_segment_squared({lo.x(), hi.y()}, a, b));
  best = std::min(best, point_segment_squared({hi.x(), lo.y()}, a, b));
  return std::sqrt(best);
}

// Visits the cells of the square ring at Chebyshev distance `r` around (col, row).
template <typename Visit>
bool for_each_in_ring(int col, int row, int r, Visit&& visit) {
  if (r == 0) return visit(col, row);
  for (int c = col - r; c <= col + r; ++c) {
    if (!visit(c, row - r) || !visit(c, row + r)) return false;
  }
  for (int rr = row - r + 1; rr <= row + r - 1; ++rr) {
    if (!visit(col - r, rr) || !visit(col + r, rr)) return false;
  }
  return true;
}

}  // namespace

// Four times the squared distance, in cells, from a cell centre to an
// obstacle square dc columns and dr rows away is h(dc) + h(dr) with
// h(0) = 0 and h(n) = (2|n| - 1)^2: separable, so a pass down the columns
// (distance to the nearest obstacle row in the column) and a pass along the
// rows (the best column within the reach) give it exactly. The row pass is
// a min over a window of 2 x reach + 1, which the compiler vectorises; rows
// are padded with obstacle columns, since outside the grid is unknown.
ClearanceMap::ClearanceMap(const grid::OccupancyGrid& grid, double max_distance)
    : width_(grid.width()), height_(grid.height()), resolution_(grid.resolution()), origin_(grid.origin()) {
  if (grid.empty()) throw std::invalid_argument("ClearanceMap: empty grid");
  if (!(max_distance >= 0.0) || max_distance / resolution_ > kMaxReachCells) {
    throw std::invalid_argument("ClearanceMap: max_distance must be between 0 and 4096 cells");
  }
  reach_cells_ = std::max(1, static_cast<int>(std::ceil(max_distance / resolution_ - 1e-9)));
  const int reach = reach_cells_;
  const auto w = static_cast<std::size_t>(width_);
  const auto h = static_cast<std::size_t>(height_);

  states_.assign(grid.cells().begin(), grid.cells().end());

  // Column pass: whole cells to the nearest obstacle in the column (rows -1
  // and height are outside, hence obstacles), capped at reach + 1. Written
  // without branches so that it runs on whole rows at once.
  const float cap = 4.0f * static_cast<float>(reach) * static_cast<float>(reach);
  const auto far = static_cast<std::int16_t>(reach + 1);
  std::vector<std::int16_t> column(w * h);
  std::vector<std::int16_t> running(w, 0);
  for (std::size_t row = 0; row < h; ++row) {
    const grid::CellState* state = &states_[row * w];
    std::int16_t* out = &column[row * w];
    for (std::size_t col = 0; col < w; ++col) {
      const auto free = static_cast<std::int16_t>(state[col] == grid::CellState::free);
      running[col] = static_cast<std::int16_t>(std::min<std::int16_t>(static_cast<std::int16_t>(running[col] + 1), far) * free);
      out[col] = running[col];
    }
  }
  std::fill(running.begin(), running.end(), std::int16_t{0});
  quarter_squared_.resize(w * h);
  for (std::size_t row = h; row-- > 0;) {
    const std::int16_t* in = &column[row * w];
    float* out = &quarter_squared_[row * w];
    for (std::size_t col = 0; col < w; ++col) {
      const auto free = static_cast<std::int16_t>(in[col] != 0);
      running[col] = static_cast<std::int16_t>(std::min<std::int16_t>(static_cast<std::int16_t>(running[col] + 1), far) * free);
      const float cells = static_cast<float>(std::min(in[col], running[col]));
      const float odd = 2.0f * cells - 1.0f;
      // (2 cells - 1)^2, and 0 on an obstacle (cells == 0) without a branch.
      out[col] = std::min(odd * odd, cap) * std::min(cells, 1.0f);
    }
  }

  // Row pass.
  std::vector<float> padded(w + 2 * static_cast<std::size_t>(reach), 0.0f);
  float* const row_in = padded.data() + reach;
  for (std::size_t row = 0; row < h; ++row) {
    float* out = &quarter_squared_[row * w];
    std::copy(out, out + w, row_in);
    for (int d = 1; d <= reach; ++d) {
      const float odd = 2.0f * static_cast<float>(d) - 1.0f;
      const float step = odd * odd;
      if (step >= cap) break;
      const float* left = row_in - d;
      const float* right = row_in + d;
      for (std::size_t col = 0; col < w; ++col) {
        out[col] = std::min(out[col], std::min(left[col], right[col]) + step);
      }
    }
  }
}

double ClearanceMap::at(int col, int row) const {
  return 0.5 * std::sqrt(static_cast<double>(quarter_squared(col, row))) * resolution_;
}

Eigen::Vector2i ClearanceMap::cell_of(const Eigen::Vector2d& point) const {
  return grid::cell_containing(point, origin_, resolution_);
}

Eigen::Vector2d ClearanceMap::cell_centre(int col, int row) const {
  return origin_ + (Eigen::Vector2d(col, row) + Eigen::Vector2d::Constant(0.5)) * resolution_;
}

double ClearanceMap::point_clearance(const Eigen::Vector2d& point, double limit) const {
  return segment_clearance(point, point, limit);
}

bool ClearanceMap::scan_around(int col, int row, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                               double& best, double stop_below) const {
  // Every point of the segment inside cell (col, row) is at least r - 1
  // cells from any square of ring r, so rings beyond best cannot matter.
  for (int r = 0; (r - 1) * resolution_ < best; ++r) {
    const bool go_on = for_each_in_ring(col, row, r, [&](int c, int rr) {
      if (!is_obstacle(c, rr)) return true;
      const Eigen::Vector2d lo = origin_ + Eigen::Vector2d(c, rr) * resolution_;
      const Eigen::Vector2d hi = lo + Eigen::Vector2d::Constant(resolution_);
      best = std::min(best, segment_box_distance(from, to, lo, hi));
      return !(best < stop_below);
    });
    if (!go_on) return false;
  }
  return true;
}

double ClearanceMap::segment_search(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double limit,
                                    double stop_below) const {
  double best = limit;
  // A cell whose centre is D cells from every obstacle holds no point closer
  // than D - half a diagonal: skip it when that is already beyond best.
  // Compared as quarter squares, as stored.
  double skip_at_or_above = 0.0;
  const auto update_skip = [&] {
    const double cells = 2.0 * best / resolution_ + 2.0 * kHalfDiagonal;
    skip_at_or_above = cells * cells;
  };
  update_skip();
  grid::detail::traverse_segment((from - origin_) / resolution_, (to - origin_) / resolution_,
                                 [&](const Eigen::Vector2i& cell, double) {
    // A capped value (at the reach) is a lower bound, which is all the skip needs.
    if (contains(cell.x(), cell.y()) && quarter_squared(cell.x(), cell.y()) >= skip_at_or_above) return true;
    const double before = best;
    const bool go_on = scan_around(cell.x(), cell.y(), from, to, best, stop_below);
    if (best < before) update_skip();
    return go_on && best > 0.0;  // nothing is closer than touching
  });
  return best;
}

double ClearanceMap::segment_clearance(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double limit) const {
  return segment_search(from, to, limit, -std::numeric_limits<double>::infinity());
}

bool ClearanceMap::segment_keeps(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double required) const {
  const double stop_below = required - kClearanceTolerance;
  return !(segment_search(from, to, required, stop_below) < stop_below);
}

double ClearanceMap::polyline_clearance(std::span<const Eigen::Vector2d> points, double limit) const {
  if (points.empty()) return limit;
  if (points.size() == 1) return point_clearance(points[0], limit);
  double best = limit;
  for (std::size_t i = 1; i < points.size(); ++i) best = segment_clearance(points[i - 1], points[i], best);
  return best;
}

}  // namespace playerkit::wavefront
