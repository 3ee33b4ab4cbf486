#include "algorithms/grid/square_caster.hpp"

#include "algorithms/grid/square_caster_lanes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace playerkit::grid {
namespace {

constexpr int kMostClearance = 255;
// Fewer rays than this take the scalar walk (see ranges()).
constexpr std::size_t kFewestRaysForVectors = 32;
// Walks a batch advances side by side: each step is a chain of dependent
// arithmetic and a memory read, which independent walks overlap (4 measured
// faster than 2, 3, 6 or 8 on the build machine).
constexpr std::size_t kSideBySide = 4;
using lanes::kFloorShift;
using lanes::kNeverInverse;
using lanes::kNoComponent;
using lanes::kReadPadding;

bool square_caster_stops(CellState state, RayStop stop) {
  return stop == RayStop::occupied ? state == CellState::occupied : state != CellState::free;
}

int floor_cell(double cells) {
  return static_cast<int>(static_cast<long long>(cells + kFloorShift) - static_cast<long long>(kFloorShift));
}

}  // namespace

namespace {

// Per cell, the Chebyshev distance in cells (capped at kMostClearance) to the
// nearest cell that stops a ray: two raster passes over the 8 neighbours
// give it exactly. Cells off the grid count as clear (a ray leaving the grid
// is answered max_range before it could need them): the grid is framed by a
// border at the cap, so the passes need no bounds checks. Each pass takes a
// row's three neighbours in the row before it first (independent cells, so
// the compiler can take many at once), then the neighbour in the same row,
// which only a sweep can.
std::vector<std::uint8_t> chebyshev_clearance(const OccupancyGrid& grid, RayStop stop, std::size_t padding) {
  const auto width = static_cast<std::size_t>(grid.width());
  const auto height = static_cast<std::size_t>(grid.height());
  const std::size_t stride = width + 2;
  std::vector<std::uint8_t> framed(stride * (height + 2), kMostClearance);
  for (std::size_t row = 0; row < height; ++row) {
    std::uint8_t* cells = &framed[(row + 1) * stride + 1];
    for (std::size_t col = 0; col < width; ++col) {
      if (square_caster_stops(grid.at(static_cast<int>(col), static_cast<int>(row)), stop)) cells[col] = 0;
    }
  }
  // A cell never rises above its value (at most the cap), so "neighbour + 1"
  // needs no saturation: the minimum with the cell stays in a byte.
  const auto take_row = [&](std::uint8_t* cells, const std::uint8_t* beside) {
    for (std::size_t col = 1; col <= width; ++col) {
      const int nearest = std::min({beside[col - 1], beside[col], beside[col + 1]});
      cells[col] = static_cast<std::uint8_t>(std::min<int>(cells[col], nearest + 1));
    }
  };
  for (std::size_t row = 1; row <= height; ++row) {
    std::uint8_t* cells = &framed[row * stride];
    take_row(cells, cells - stride);
    int run = kMostClearance;  // the frame
    for (std::size_t col = 1; col <= width; ++col) cells[col] = static_cast<std::uint8_t>(run = std::min<int>(cells[col], run + 1));
  }
  for (std::size_t row = height; row >= 1; --row) {
    std::uint8_t* cells = &framed[row * stride];
    take_row(cells, cells + stride);
    int run = kMostClearance;
    for (std::size_t col = width; col >= 1; --col) cells[col] = static_cast<std::uint8_t>(run = std::min<int>(cells[col], run + 1));
  }
  std::vector<std::uint8_t> clearance(width * height + padding, kMostClearance);
  for (std::size_t row = 0; row < height; ++row) {
    std::copy_n(&framed[(row + 1) * stride + 1], width, &clearance[row * width]);
  }
  return clearance;
}

}  // namespace

SquareCaster::SquareCaster(const OccupancyGrid& grid, RayStop stop)
    : stop_(stop), width_(grid.width()), height_(grid.height()), resolution_(grid.resolution()), origin_(grid.origin()) {
  if (grid.empty()) return;
  clearance_ = chebyshev_clearance(grid, stop, kReadPadding);
}

SquareCaster::Start SquareCaster::start(Walk& walk, const Ray& ray) const {
  Start begun{.walks = false, .col = 0, .row = 0, .range = ray.max_range};
  if (width_ == 0 || !(ray.max_range > 0.0)) return begun;
  if (!std::isfinite(ray.direction.x()) || !std::isfinite(ray.direction.y())) return begun;
  const Start from = start_origin(walk, ray.origin, ray.max_range);
  if (!from.walks) return begun;
  begun.col = from.col;
  begun.row = from.row;
  begun.clearance = from.clearance;
  if (begun.clearance == 0) {  // in a stopping cell
    begun.range = 0.0;
    return begun;
  }
  // No direction: the first cell is all it crosses.
  begun.walks = start_direction(walk, ray.direction);
  return begun;
}

SquareCaster::Start SquareCaster::start_origin(Walk& walk, const Eigen::Vector2d& origin, double max_range) const {
  // Cell units, computed as cast_ray computes them.
  if (!(origin.x() == walk.from_x && origin.y() == walk.from_y)) {
    walk.x = (origin.x() - origin_.x()) / resolution_;
    walk.y = (origin.y() - origin_.y()) / resolution_;
    walk.from_x = origin.x();
    walk.from_y = origin.y();
  }
  if (!(max_range == walk.from_range)) {
    walk.length = max_range / resolution_;
    walk.from_range = max_range;
  }
  Start from{.walks = false, .col = 0, .row = 0, .range = max_range};
  if (!(walk.x >= 0.0 && walk.y >= 0.0 && walk.x < width_ && walk.y < height_)) return from;
  from.walks = true;
  from.col = static_cast<int>(walk.x);
  from.row = static_cast<int>(walk.y);
  from.clearance = clearance_[static_cast<std::size_t>(from.row) * static_cast<std::size_t>(width_) +
                              static_cast<std::size_t>(from.col)];
  return from;
}

bool SquareCaster::start_direction(Walk& walk, const Eigen::Vector2d& direction) const {
  const double dx = direction.x(), dy = direction.y();
  const bool moves_x = std::abs(dx) > kNoComponent, moves_y = std::abs(dy) > kNoComponent;
  if (!moves_x && !moves_y) return false;
  walk.dx = dx;
  walk.dy = dy;
  walk.step_x = dx < 0.0 && moves_x ? -1 : 1;
  walk.step_y = dy < 0.0 && moves_y ? -1 : 1;
  // Both reciprocals in one packed division (SSE2): two divisions a ray
  // were a quarter of starting a laser's rays.
  const Eigen::Array2d inverse = 1.0 / direction.array();
  walk.inverse_x = moves_x ? inverse.x() : kNeverInverse;
  walk.inverse_y = moves_y ? inverse.y() : kNeverInverse;
  return true;
}

// One step, written without branches on the map (arithmetic and selects,
// never a path computed only when taken, so that the compiler has no reason
// to branch): from the cell (col, row), whose clearance k >= 1 the caller
// holds, to the cell just past the clear square of side 2k - 1 around it,
// where the ray leaves the square; the step reads that cell's clearance
// into `clearance`. Returns kWalking, or kHit with the position moved to
// the stopping cell just entered, or kGone (position unchanged) when the
// ray passed max_range or left the grid. Reading the next cell within the
// step, rather than at the start of the next one, saves the step that
// would only find the wall (one of about seven a ray).
[[gnu::always_inline]] inline int SquareCaster::advance(const Walk& walk, int& col, int& row, double& along,
                                                        int& clearance) const {
  const int reach = clearance;
  // The square's far borders in the ray's direction, and where it crosses them.
  const int jump_x = walk.step_x * reach, jump_y = walk.step_y * reach;
  const double border_x = col + jump_x + (walk.step_x < 0);
  const double border_y = row + jump_y + (walk.step_y < 0);
  const double exit_x = (border_x - walk.x) * walk.inverse_x;
  const double exit_y = (border_y - walk.y) * walk.inverse_y;
  const int by_x = exit_x <= exit_y;  // x first at a tie, as cast_ray
  double leaves = std::min(exit_x, exit_y);
  // The cell entered: past the border on the axis it leaves by, and where
  // the ray is on the other. Rounding may put that one a cell off where the
  // ray passes within rounding of a cell corner: a tie either cell answers.
  // Chosen by masks rather than a select, which the compiler may turn into
  // a branch that no predictor guesses.
  int cell_x = floor_cell(walk.x + leaves * walk.dx);
  int cell_y = floor_cell(walk.y + leaves * walk.dy);
  // Through a cell corner (exactly, or within rounding of one), the floor
  // can give a cell behind the walk's: going down or left, the crossing's
  // floor at a corner is the cell beside the corner on the near side. The
  // ray leaves that cell where it already is, so the step does not move it
  // on, and the floor of that step sends it back to the cell before: walked
  // as the rest, it bounces between the two for ever. So a step that does
  // not move the ray on keeps it from going back on either axis (the cell
  // ahead of a corner is its diagonal neighbour), and does not move `along`
  // back. Every walk then ends: `along` takes finitely many values and never
  // falls, and while it stands still each step moves the cell on by one or
  // more on one axis and back on neither. Rare enough for a branch.
  if (!(leaves > along)) [[unlikely]] {
    cell_x = walk.step_x > 0 ? std::max(cell_x, col) : std::min(cell_x, col);
    cell_y = walk.step_y > 0 ? std::max(cell_y, row) : std::min(cell_y, row);
    leaves = along;
  }
  const int leaves_x_mask = -by_x;  // all ones when the ray leaves by x
  const int next_col = cell_x ^ ((cell_x ^ (col + jump_x)) & leaves_x_mask);
  const int next_row = (row + jump_y) ^ (((row + jump_y) ^ cell_y) & leaves_x_mask);
  const int gone = !(leaves < walk.length) | (static_cast<unsigned>(next_col) >= static_cast<unsigned>(width_)) |
                   (static_cast<unsigned>(next_row) >= static_cast<unsigned>(height_));
  // A gone ray reads its own cell again rather than one off the grid.
  col = gone != 0 ? col : next_col;
  row = gone != 0 ? row : next_row;
  along = gone != 0 ? along : leaves;
  clearance = clearance_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col)];
  return gone != 0 ? kGone : (clearance == 0 ? kHit : kWalking);
}

double SquareCaster::clear_around(const Eigen::Vector2d& point) const {
  if (width_ == 0) return 0.0;
  const double x = (point.x() - origin_.x()) / resolution_, y = (point.y() - origin_.y()) / resolution_;
  if (!(x >= 0.0 && y >= 0.0 && x < width_ && y < height_)) return 0.0;
  const int clearance = clearance_[static_cast<std::size_t>(static_cast<int>(y)) * static_cast<std::size_t>(width_) +
                                   static_cast<std::size_t>(static_cast<int>(x))];
  return clearance == 0 ? 0.0 : (clearance - 1) * resolution_;
}

double SquareCaster::range(const Eigen::Vector2d& origin, double angle, double max_range) const {
  return range(origin, Eigen::Vector2d(std::cos(angle), std::sin(angle)), max_range);
}

double SquareCaster::range(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction, double max_range) const {
  Walk walk;
  const Start begun = start(walk, {origin, direction, max_range});
  if (!begun.walks) return begun.range;
  int col = begun.col, row = begun.row, clearance = begun.clearance;
  double along = 0.0;
  for (;;) {
    const int status = advance(walk, col, row, along, clearance);
    if (status != kWalking) return status == kHit ? std::min(along * resolution_, max_range) : max_range;
  }
}

void SquareCaster::ranges(std::span<const Ray> rays, std::span<double> ranges, Walker walker) const {
  if (rays.size() != ranges.size()) {
    throw std::invalid_argument("SquareCaster::ranges: " + std::to_string(rays.size()) + " rays but room for " +
                                std::to_string(ranges.size()) + " ranges");
  }
  if (takes_vector_walk(rays.size(), walker)) {
    vector_ranges(rays, ranges);
  } else {
    scalar_ranges(rays, ranges);
  }
}

bool SquareCaster::has_vector_walker() { return lanes::available(); }

bool SquareCaster::takes_vector_walk(std::size_t rays, Walker walker) const {
  // The vector walk finds cells by an index in 32 bits, and pays for its
  // sixteen lanes only with enough rays to keep them busy (a sonar ring of
  // 12 ran a fifth slower on it, 1000 rings in the hospital world).
  const bool indexable = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) < (std::size_t{1} << 31);
  return walker == Walker::automatic && indexable && rays >= kFewestRaysForVectors && has_vector_walker();
}

lanes::LaneStart SquareCaster::lane_start(const Walk& walk, const Start& begun, double max_range) {
  return {walk.x,
          walk.y,
          walk.dx,
          walk.dy,
          walk.inverse_x,
          walk.inverse_y,
          walk.length,
          static_cast<double>(walk.step_x),
          walk.step_x < 0 ? 1.0 : 0.0,
          static_cast<double>(walk.step_y),
          walk.step_y < 0 ? 1.0 : 0.0,
          static_cast<double>(begun.col),
          static_cast<double>(begun.row),
          static_cast<double>(begun.clearance),
          max_range};
}

namespace {

// The vector walk's starts, reused from call to call: no allocation once
// grown, one set a thread.
struct LaneStarts {
  std::vector<lanes::LaneStart> starts;
  std::vector<std::size_t> ray;  // which ray each start is
  std::size_t count = 0;

  void prepare(std::size_t rays) {
    starts.resize(rays);
    ray.resize(rays);
    count = 0;
  }
  void add(const lanes::LaneStart& start, std::size_t index) {
    starts[count] = start;
    ray[count] = index;
    ++count;
  }
};

thread_local LaneStarts lane_starts;

}  // namespace

void SquareCaster::vector_ranges(std::span<const Ray> rays, std::span<double> ranges) const {
  // Every ray's start first, in a loop of its own; rays answered without a
  // walk are answered here.
  lane_starts.prepare(rays.size());
  Walk walk;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Start begun = start(walk, rays[i]);
    if (begun.walks) {
      lane_starts.add(lane_start(walk, begun, rays[i].max_range), i);
    } else {
      ranges[i] = begun.range;
    }
  }
  lanes::walk({clearance_.data(), width_, height_, resolution_},
              std::span(lane_starts.starts).first(lane_starts.count),
              std::span(lane_starts.ray).first(lane_starts.count), ranges);
}

void SquareCaster::fan_ranges(const Eigen::Vector2d& origin, std::span<const Eigen::Vector2d> directions,
                              double max_range, std::span<double> ranges, Walker walker) const {
  if (directions.size() != ranges.size()) {
    throw std::invalid_argument("SquareCaster::fan_ranges: " + std::to_string(directions.size()) +
                                " directions but room for " + std::to_string(ranges.size()) + " ranges");
  }
  if (!takes_vector_walk(directions.size(), walker) || width_ == 0 || !(max_range > 0.0)) {
    thread_local std::vector<Ray> rays;
    rays.clear();
    for (const Eigen::Vector2d& direction : directions) rays.push_back({origin, direction, max_range});
    this->ranges(rays, ranges, walker);
    return;
  }
  // start() for each ray, its origin's part done once: the same outcomes in
  // the same order of precedence.
  lane_starts.prepare(directions.size());
  Walk walk;
  const Start from = start_origin(walk, origin, max_range);
  for (std::size_t i = 0; i < directions.size(); ++i) {
    const Eigen::Vector2d& direction = directions[i];
    if (!std::isfinite(direction.x()) || !std::isfinite(direction.y()) || !from.walks) {
      ranges[i] = max_range;
    } else if (from.clearance == 0) {
      ranges[i] = 0.0;
    } else if (!start_direction(walk, direction)) {
      ranges[i] = max_range;
    } else {
      lane_starts.add(lane_start(walk, from, max_range), i);
    }
  }
  lanes::walk({clearance_.data(), width_, height_, resolution_},
              std::span(lane_starts.starts).first(lane_starts.count),
              std::span(lane_starts.ray).first(lane_starts.count), ranges);
}

void SquareCaster::scalar_ranges(std::span<const Ray> rays, std::span<double> ranges) const {
  // Walks side by side; a walk that ends takes the next ray. The rays
  // answered without a walk are answered as they are taken.
  std::size_t next = 0;
  const auto take_next = [&](Walk& walk, std::size_t& index, int& col, int& row, double& along, int& clearance) {
    while (next < rays.size()) {
      index = next++;
      const Start begun = start(walk, rays[index]);
      if (begun.walks) {
        col = begun.col;
        row = begun.row;
        clearance = begun.clearance;
        along = 0.0;
        return true;
      }
      ranges[index] = begun.range;
    }
    return false;
  };
  const auto finish = [&](int status, std::size_t index, double along) {
    const double max_range = rays[index].max_range;
    ranges[index] = status == kHit ? std::min(along * resolution_, max_range) : max_range;
  };
  std::array<Walk, kSideBySide> walks;
  std::array<std::size_t, kSideBySide> index{};
  std::array<int, kSideBySide> col{}, row{}, clearance{};
  std::array<double, kSideBySide> along{};
  std::array<bool, kSideBySide> walking{};
  bool all_walking = true;
  for (std::size_t k = 0; k < kSideBySide; ++k) {
    walking[k] = take_next(walks[k], index[k], col[k], row[k], along[k], clearance[k]);
    all_walking = all_walking && walking[k];
  }
  // Unrolled, so that each walk's position stays in registers.
  while (all_walking) {
    std::array<int, kSideBySide> status{};
#pragma GCC unroll 4
    for (std::size_t k = 0; k < kSideBySide; ++k) status[k] = advance(walks[k], col[k], row[k], along[k], clearance[k]);
#pragma GCC unroll 4
    for (std::size_t k = 0; k < kSideBySide; ++k) {
      if (status[k] == kWalking) continue;
      finish(status[k], index[k], along[k]);
      walking[k] = take_next(walks[k], index[k], col[k], row[k], along[k], clearance[k]);
      all_walking = all_walking && walking[k];
    }
  }
  // No rays left: finish the walks still going, one by one.
  for (std::size_t k = 0; k < kSideBySide; ++k) {
    while (walking[k]) {
      const int status = advance(walks[k], col[k], row[k], along[k], clearance[k]);
      if (status != kWalking) {
        finish(status, index[k], along[k]);
        walking[k] = false;
      }
    }
  }
}

}  // namespace playerkit::grid
