#include "sim/worldfile/world_loader_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "map/map_file.hpp"
#include "sim/worldfile/worldfile_error.hpp"
#include "sim/worldfile/worldfile_limits.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

// Cell edges and wall edges that coincide in exact arithmetic may differ by
// rounding; a wall only touching a cell must not occupy it.
constexpr double kEdgeTolerance = 1e-9;

// The cell range [first, last] whose interiors overlap [low, high].
std::pair<long long, long long> overlapped_cells(double low, double high, double origin, double resolution) {
  const double first = std::floor((low - origin) / resolution + kEdgeTolerance);
  const double last = std::ceil((high - origin) / resolution - kEdgeTolerance) - 1.0;
  constexpr double limit = 1e12;
  return {static_cast<long long>(std::clamp(first, -limit, limit)),
          static_cast<long long>(std::clamp(last, -limit, limit))};
}

std::array<Eigen::Vector2d, 4> corners_of(const WallRectangle& wall) {
  const Eigen::Vector2d half = wall.size / 2.0;
  return {wall.centre.transform({-half.x(), -half.y()}), wall.centre.transform({half.x(), -half.y()}),
          wall.centre.transform({half.x(), half.y()}), wall.centre.transform({-half.x(), half.y()})};
}

// Separating-axis test of a turned rectangle against an axis-aligned cell:
// do their interiors overlap?
bool wall_overlaps_cell(const std::array<Eigen::Vector2d, 4>& corners, const Eigen::Vector2d& cell_low,
                        double resolution) {
  const std::array<Eigen::Vector2d, 4> cell = {cell_low, cell_low + Eigen::Vector2d(resolution, 0.0),
                                               cell_low + Eigen::Vector2d(resolution, resolution),
                                               cell_low + Eigen::Vector2d(0.0, resolution)};
  const std::array<Eigen::Vector2d, 4> axes = {Eigen::Vector2d::UnitX(), Eigen::Vector2d::UnitY(),
                                               (corners[1] - corners[0]).normalized(),
                                               (corners[3] - corners[0]).normalized()};
  for (const Eigen::Vector2d& axis : axes) {
    if (!axis.allFinite()) continue;  // a degenerate wall: its other axis decides
    double wall_low = std::numeric_limits<double>::infinity(), wall_high = -wall_low;
    double cell_min = wall_low, cell_max = -wall_low;
    for (const auto& point : corners) {
      wall_low = std::min(wall_low, axis.dot(point));
      wall_high = std::max(wall_high, axis.dot(point));
    }
    for (const auto& point : cell) {
      cell_min = std::min(cell_min, axis.dot(point));
      cell_max = std::max(cell_max, axis.dot(point));
    }
    if (std::min(wall_high, cell_max) - std::max(wall_low, cell_min) <= kEdgeTolerance * resolution) return false;
  }
  return true;
}

// The x-extent of a turned wall within the band y0 <= y <= y1: its corners
// inside the band and the points where its edges cross the band's lines.
// Empty (low > high) when the wall misses the band.
std::pair<double, double> x_extent_in_band(const std::array<Eigen::Vector2d, 4>& corners, double y0, double y1) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  const auto take = [&](double x) {
    low = std::min(low, x);
    high = std::max(high, x);
  };
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector2d& a = corners[i];
    const Eigen::Vector2d& b = corners[(i + 1) % corners.size()];
    if (a.y() >= y0 && a.y() <= y1) take(a.x());
    for (const double y : {y0, y1}) {
      if ((a.y() - y) * (b.y() - y) < 0.0) take(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
  }
  return {low, high};
}

bool turned_by_right_angles(double yaw) {
  const double turn = std::fmod(std::abs(yaw), std::numbers::pi / 2.0);
  return turn < 1e-12 || std::numbers::pi / 2.0 - turn < 1e-12;
}

// The bitmap whose pixels become the map's cells: the finest, when it is
// coarser than `resolution` asks and every bitmap is axis-aligned (a turned
// one keeps the cell `resolution`, which then follows its edges more
// closely). Stage 1.3's grid starts at (0, 0), so there the pixels must
// line up with it.
const PixelLattice* cell_lattice(const MapPlan& plan) {
  if (plan.bitmaps.empty()) return nullptr;
  const auto finest = std::min_element(plan.bitmaps.begin(), plan.bitmaps.end(),
                                       [](const PixelLattice& a, const PixelLattice& b) { return a.pixel < b.pixel; });
  if (!(finest->pixel > plan.resolution * (1.0 + 1e-9))) return nullptr;
  if (!std::all_of(plan.bitmaps.begin(), plan.bitmaps.end(), [](const PixelLattice& bitmap) { return bitmap.axis_aligned; })) {
    return nullptr;
  }
  if (plan.positive_quadrant) {
    for (int axis = 0; axis < 2; ++axis) {
      const double cells = finest->corner[axis] / finest->pixel;
      if (std::abs(cells - std::round(cells)) > 1e-6) return nullptr;
    }
  }
  return &*finest;
}

}  // namespace

void mark_wall(grid::OccupancyGrid& grid, const WallRectangle& wall) {
  const auto corners = corners_of(wall);
  Eigen::Vector2d low = corners[0], high = corners[0];
  for (const auto& corner : corners) {
    low = low.cwiseMin(corner);
    high = high.cwiseMax(corner);
  }
  const double resolution = grid.resolution();
  const auto [first_col, last_col] = overlapped_cells(low.x(), high.x(), grid.origin().x(), resolution);
  const auto [first_row, last_row] = overlapped_cells(low.y(), high.y(), grid.origin().y(), resolution);
  const long long col_begin = std::max(first_col, 0LL), col_end = std::min(last_col, grid.width() - 1LL);
  const long long row_begin = std::max(first_row, 0LL), row_end = std::min(last_row, grid.height() - 1LL);
  const bool axis_aligned = turned_by_right_angles(wall.centre.yaw);
  for (long long row = row_begin; row <= row_end; ++row) {
    long long row_col_begin = col_begin, row_col_end = col_end;
    if (!axis_aligned) {
      // Only the cells under the wall's extent in this row, give or take one
      // (the overlap test below decides): a long wall at 45 degrees has a
      // bounding box of length^2 / 2 cells, and testing all of them took
      // minutes on a large turned bitmap (found by fuzzing).
      const double y0 = grid.origin().y() + static_cast<double>(row) * resolution;
      const auto [x_low, x_high] = x_extent_in_band(corners, y0, y0 + resolution);
      if (!(x_low <= x_high)) continue;
      const auto [first, last] = overlapped_cells(x_low, x_high, grid.origin().x(), resolution);
      row_col_begin = std::max(col_begin, first - 1);
      row_col_end = std::min(col_end, last + 1);
    }
    for (long long col = row_col_begin; col <= row_col_end; ++col) {
      const int c = static_cast<int>(col), r = static_cast<int>(row);
      if (!axis_aligned) {
        const Eigen::Vector2d cell_low = grid.origin() + Eigen::Vector2d(static_cast<double>(col) * resolution,
                                                                         static_cast<double>(row) * resolution);
        if (!wall_overlaps_cell(corners, cell_low, resolution)) continue;
      }
      grid.set(c, r, grid::CellState::occupied);
    }
  }
}

void add_bitmap_walls(const BitmapPlacement& bitmap, MapPlan& plan, std::vector<std::string>& warnings) {
  map::MapLoadOptions options;
  options.resolution = 1.0;  // only the pixels are used
  if (bitmap.walls == WallPixels::non_zero) {
    options.negate = true;  // occupancy v / 255: above 0 for any non-zero pixel
    options.occupied_threshold = 0.0;
  } else {
    options.occupied_threshold = 0.5;  // (255 - v) / 255 > 0.5 exactly when v <= 127
  }
  options.free_threshold = 0.0;
  grid::OccupancyGrid pixels;
  try {
    pixels = map::load_map(bitmap.file, options);
  } catch (const map::MapFileError& error) {
    throw WorldFileError(bitmap.where, std::string("cannot read the bitmap: ") + error.what());
  }
  const auto wall_at = [&](int col, int row) { return pixels.at(col, row) == grid::CellState::occupied; };

  double sx = 0.0, sy = 0.0, centre_x = 0.0, centre_y = 0.0;
  if (bitmap.metres_per_pixel) {
    sx = sy = *bitmap.metres_per_pixel;
    if (bitmap.centred) {
      centre_x = pixels.width() / 2.0;
      centre_y = pixels.height() / 2.0;
    }
  } else {
    int first_col = pixels.width(), last_col = -1, first_row = pixels.height(), last_row = -1;
    for (int row = 0; row < pixels.height(); ++row) {
      for (int col = 0; col < pixels.width(); ++col) {
        if (!wall_at(col, row)) continue;
        first_col = std::min(first_col, col);
        last_col = std::max(last_col, col);
        first_row = std::min(first_row, row);
        last_row = std::max(last_row, row);
      }
    }
    if (last_col < 0) {
      warnings.push_back(located(bitmap.where, "the bitmap " + text::excerpt(bitmap.file.filename().string()) +
                                                   " has no dark pixels: no walls"));
      return;
    }
    sx = bitmap.stretch_to.x() / (last_col + 1 - first_col);
    sy = bitmap.stretch_to.y() / (last_row + 1 - first_row);
    centre_x = (first_col + last_col + 1) / 2.0;
    centre_y = (first_row + last_row + 1) / 2.0;
  }
  if (!(sx > 0.0) || !(sy > 0.0)) return;
  plan.bitmaps.push_back({.pixel = std::min(sx, sy),
                          .corner = bitmap.pose.transform({-centre_x * sx, -centre_y * sy}),
                          .axis_aligned = turned_by_right_angles(bitmap.pose.yaw)});

  std::vector<WallRectangle>& walls = plan.walls;
  for (int row = 0; row < pixels.height(); ++row) {
    for (int col = 0; col < pixels.width();) {
      if (!wall_at(col, row)) {
        ++col;
        continue;
      }
      const int run_start = col;
      while (col < pixels.width() && wall_at(col, row)) ++col;
      const Eigen::Vector2d local_centre(((run_start + col) / 2.0 - centre_x) * sx, (row + 0.5 - centre_y) * sy);
      const Eigen::Vector2d centre = bitmap.pose.transform(local_centre);
      walls.push_back(WallRectangle{{centre.x(), centre.y(), bitmap.pose.yaw},
                                    {(col - run_start) * sx, sy}});
    }
  }
}

grid::OccupancyGrid build_map(const MapPlan& plan, std::vector<std::string>& warnings) {
  const double infinity = std::numeric_limits<double>::infinity();
  Eigen::Vector2d low(infinity, infinity), high(-infinity, -infinity);
  for (const WallRectangle& wall : plan.walls) {
    for (const auto& corner : corners_of(wall)) {
      low = low.cwiseMin(corner);
      high = high.cwiseMax(corner);
    }
  }
  for (const Eigen::Vector2d& point : plan.must_cover) {
    low = low.cwiseMin(point);
    high = high.cwiseMax(point);
  }
  const bool empty = !(low.x() <= high.x());
  if (plan.positive_quadrant) {
    low = Eigen::Vector2d::Zero();
    high = (empty ? Eigen::Vector2d::Zero() : high).cwiseMax(plan.minimum_size).cwiseMax(3.0 * plan.resolution);
  } else if (empty) {
    low = Eigen::Vector2d(-5.0, -5.0);
    high = Eigen::Vector2d(5.0, 5.0);
  } else {
    // Stage 3/4 worlds are unbounded: a margin around what is there.
    constexpr double margin = 1.0;
    low -= Eigen::Vector2d::Constant(margin);
    high += Eigen::Vector2d::Constant(margin);
  }
  if (!low.allFinite() || !high.allFinite() || (high - low).maxCoeff() > kMaxWorldExtent) {
    throw WorldFileError(plan.where, "the world spans more than " + std::to_string(static_cast<long long>(kMaxWorldExtent)) +
                                         " m (from (" + std::to_string(low.x()) + ", " + std::to_string(low.y()) +
                                         ") to (" + std::to_string(high.x()) + ", " + std::to_string(high.y()) +
                                         ")): a size or pose is far too large");
  }

  // The cell, and the origin that lays cells on a bitmap's pixels when the
  // cell is that bitmap's pixel.
  const PixelLattice* lattice = cell_lattice(plan);
  if (lattice != nullptr && !plan.positive_quadrant) {
    for (int axis = 0; axis < 2; ++axis) {
      const double cells_below = std::ceil((lattice->corner[axis] - low[axis]) / lattice->pixel - 1e-9);
      low[axis] = lattice->corner[axis] - cells_below * lattice->pixel;
    }
  }
  const double cell = lattice != nullptr ? lattice->pixel : plan.resolution;
  double finest_pixel = std::numeric_limits<double>::infinity();
  for (const PixelLattice& bitmap : plan.bitmaps) finest_pixel = std::min(finest_pixel, bitmap.pixel);

  double resolution = cell;
  const auto cells_along = [&](double length, double size) { return std::max(1.0, std::ceil(length / size - 1e-6)); };
  const auto cell_count = [&](double size) {
    return cells_along(high.x() - low.x(), size) * cells_along(high.y() - low.y(), size);
  };
  const double wanted = cell_count(resolution);
  if (wanted > static_cast<double>(grid::kMaxGridCells)) {
    double factor = std::ceil(std::sqrt(wanted / static_cast<double>(grid::kMaxGridCells)));
    while (cell_count(cell * factor) > static_cast<double>(grid::kMaxGridCells)) factor += 1.0;
    resolution = cell * factor;
    const std::string area = std::to_string(high.x() - low.x()) + " x " + std::to_string(high.y() - low.y()) + " m";
    if (resolution > finest_pixel * (1.0 + 1e-9)) {
      throw WorldFileError(plan.where, "the world covers " + area + ": at a cell of " + std::to_string(cell) +
                                           " m it needs " + std::to_string(static_cast<long long>(wanted)) +
                                           " cells, more than the limit of " + std::to_string(grid::kMaxGridCells) +
                                           ", and a cell coarser than the bitmap's pixel (" +
                                           std::to_string(finest_pixel) + " m) would lose walls");
    }
    warnings.push_back(located(plan.where, "the map's cell is " + std::to_string(resolution) + " m instead of " +
                                               std::to_string(cell) + " m: the world covers " + area +
                                               ", which would need more than " +
                                               std::to_string(grid::kMaxGridCells) + " cells"));
  }
  const int width = static_cast<int>(cells_along(high.x() - low.x(), resolution));
  const int height = static_cast<int>(cells_along(high.y() - low.y(), resolution));
  grid::OccupancyGrid map(width, height, resolution, low, grid::CellState::free);
  for (const WallRectangle& wall : plan.walls) mark_wall(map, wall);
  if (plan.positive_quadrant && lattice != nullptr) {
    // Stage 1.3's closing wall is one `resolution` cell thick, one cell
    // inside the border; on the bitmap's coarser cells it occupies the
    // cells it overlaps.
    const double r = plan.resolution;
    const double x_end = cells_along(high.x(), r) * r, y_end = cells_along(high.y(), r) * r;
    if (x_end >= 3.0 * r && y_end >= 3.0 * r) {
      const double across = x_end - 2.0 * r, up = y_end - 2.0 * r;
      for (const WallRectangle& side : {WallRectangle{{x_end / 2.0, 1.5 * r, 0.0}, {across, r}},
                                        WallRectangle{{x_end / 2.0, y_end - 1.5 * r, 0.0}, {across, r}},
                                        WallRectangle{{1.5 * r, y_end / 2.0, 0.0}, {r, up}},
                                        WallRectangle{{x_end - 1.5 * r, y_end / 2.0, 0.0}, {r, up}}}) {
        mark_wall(map, side);
      }
    }
  } else if (plan.positive_quadrant && width >= 3 && height >= 3) {
    // Stage 1.3 closes every world with a wall one cell inside its border.
    for (int col = 1; col <= width - 2; ++col) {
      map.set(col, 1, grid::CellState::occupied);
      map.set(col, height - 2, grid::CellState::occupied);
    }
    for (int row = 1; row <= height - 2; ++row) {
      map.set(1, row, grid::CellState::occupied);
      map.set(width - 2, row, grid::CellState::occupied);
    }
  }
  return map;
}

}  // namespace playerkit::sim::worldfile
