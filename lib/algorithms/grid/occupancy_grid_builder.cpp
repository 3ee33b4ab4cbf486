#include "algorithms/grid/occupancy_grid_builder.hpp"

#include "algorithms/grid/grid_traversal.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <stdexcept>

namespace playerkit::grid {
namespace {

// Saturating the log odds keeps a cell able to change its mind after a few
// contrary readings (a door that opens), instead of needing as many as it
// ever received.
constexpr float kMinLogOdds = -2.0f;  // p ~ 0.12
constexpr float kMaxLogOdds = 3.5f;   // p ~ 0.97

std::uint64_t pack(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

Eigen::Vector2i unpack(std::uint64_t key) {
  return {static_cast<int>(static_cast<std::uint32_t>(key >> 32)),
          static_cast<int>(static_cast<std::uint32_t>(key & 0xffffffffu))};
}

bool is_probability(double p) { return p > 0.0 && p < 1.0; }

std::string format_metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

OccupancyGridBuilder::OccupancyGridBuilder(OccupancyMappingParameters parameters)
    : parameters_(parameters) {
  if (!(parameters_.resolution > 0.0) || !std::isfinite(parameters_.resolution)) {
    throw std::invalid_argument("OccupancyGridBuilder: resolution must be positive");
  }
  if (!(parameters_.max_usable_range > 0.0) || !std::isfinite(parameters_.max_usable_range)) {
    throw std::invalid_argument("OccupancyGridBuilder: max_usable_range must be positive");
  }
  if (!(parameters_.no_return_clear_range >= 0.0)) {  // NaN too
    throw std::invalid_argument("OccupancyGridBuilder: no_return_clear_range must be non-negative");
  }
  if (!(parameters_.margin >= 0.0) || !std::isfinite(parameters_.margin)) {
    throw std::invalid_argument("OccupancyGridBuilder: margin must be non-negative");
  }
  if (!is_probability(parameters_.occupied_probability) ||
      !is_probability(parameters_.free_probability)) {
    throw std::invalid_argument("OccupancyGridBuilder: probabilities must lie in (0, 1)");
  }
}

void OccupancyGridBuilder::add_scan(const geometry::Pose2& laser_pose,
                                    std::span<const double> ranges, double angle_min,
                                    double angle_increment, double max_range) {
  ++scan_count_;
  struct Beam {
    Eigen::Vector2d end;  // in cell units
    bool hit;
  };
  const double cells_per_metre = 1.0 / parameters_.resolution;
  const Eigen::Vector2d start = laser_pose.translation() * cells_per_metre;
  const Eigen::Vector2i start_cell(detail::cell_index(start.x()), detail::cell_index(start.y()));
  std::vector<Beam> beams;
  beams.reserve(ranges.size());
  Eigen::Vector2i low = start_cell, high = start_cell;
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double range = ranges[i];
    if (std::isnan(range) || range <= 0.0) continue;
    const bool no_return = range >= max_range;
    const double usable =
        no_return ? std::min({max_range, parameters_.max_usable_range, parameters_.no_return_clear_range})
                  : std::min(range, parameters_.max_usable_range);
    if (usable <= 0.0) continue;
    const double bearing = laser_pose.yaw + angle_min + static_cast<double>(i) * angle_increment;
    const Eigen::Vector2d end =
        start + usable * cells_per_metre * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
    beams.push_back({end, !no_return && range <= parameters_.max_usable_range});
    const Eigen::Vector2i end_cell(detail::cell_index(end.x()), detail::cell_index(end.y()));
    low = low.cwiseMin(end_cell);
    high = high.cwiseMax(end_cell);
  }
  if (beams.empty()) return;
  check_size(low, high);

  // Mark each cell once per scan in a window over the scan's bounding box
  // (every cell of a segment lies in the box of its end cells); a hit
  // outranks misses from other beams of the same scan.
  constexpr std::uint8_t kMiss = 1, kHit = 2;
  const Eigen::Vector2i window = high - low + Eigen::Vector2i::Ones();
  scan_marks_.assign(static_cast<std::size_t>(window.x()) * static_cast<std::size_t>(window.y()), 0);
  scan_cells_.clear();
  for (const Beam& beam : beams) {
    const Eigen::Vector2i end_cell(detail::cell_index(beam.end.x()), detail::cell_index(beam.end.y()));
    detail::traverse_segment(start, beam.end, [&](const Eigen::Vector2i& cell, double) {
      const Eigen::Vector2i local = cell - low;
      std::uint8_t& mark = scan_marks_[static_cast<std::size_t>(local.y()) * static_cast<std::size_t>(window.x()) +
                                       static_cast<std::size_t>(local.x())];
      if (mark == 0) scan_cells_.push_back(cell);
      mark = std::max(mark, beam.hit && cell == end_cell ? kHit : kMiss);
      return true;
    });
  }
  for (const Eigen::Vector2i& cell : scan_cells_) {
    const Eigen::Vector2i local = cell - low;
    const std::uint8_t mark = scan_marks_[static_cast<std::size_t>(local.y()) * static_cast<std::size_t>(window.x()) +
                                          static_cast<std::size_t>(local.x())];
    update_cell(cell, mark == kHit ? parameters_.hit_log_odds : parameters_.miss_log_odds);
  }
}

void OccupancyGridBuilder::update_cell(const Eigen::Vector2i& cell, double log_odds_change) {
  // Arithmetic shift floors negative cells into the right tile.
  const int tile_x = cell.x() >> kTileShift;
  const int tile_y = cell.y() >> kTileShift;
  const std::uint64_t tile_key = pack(tile_x, tile_y);
  if (last_tile_ == nullptr || tile_key != last_tile_key_) {
    // Map values keep their address through rehashing, so the pointer stays valid.
    last_tile_ = &tiles_.try_emplace(tile_key).first->second;
    last_tile_key_ = tile_key;
  }
  Tile& tile = *last_tile_;
  const int local_x = cell.x() - (tile_x << kTileShift);
  const int local_y = cell.y() - (tile_y << kTileShift);
  float& log_odds = tile[static_cast<std::size_t>(local_y * kTileSize + local_x)];
  log_odds = std::clamp(log_odds + static_cast<float>(log_odds_change), kMinLogOdds, kMaxLogOdds);
  if (!touched_any_) {
    touched_min_ = touched_max_ = cell;
    touched_any_ = true;
  } else {
    touched_min_ = touched_min_.cwiseMin(cell);
    touched_max_ = touched_max_.cwiseMax(cell);
  }
}

// Before the scan's window is allocated: the map so far with this scan and
// the margin must fit kMaxGridCells (it only grows from here).
void OccupancyGridBuilder::check_size(const Eigen::Vector2i& scan_low, const Eigen::Vector2i& scan_high) const {
  const Eigen::Vector2i low = touched_any_ ? touched_min_.cwiseMin(scan_low) : scan_low;
  const Eigen::Vector2i high = touched_any_ ? touched_max_.cwiseMax(scan_high) : scan_high;
  const double resolution = parameters_.resolution;
  const auto margin = static_cast<std::int64_t>(std::ceil(parameters_.margin / resolution));
  const std::int64_t width = std::int64_t{high.x()} - low.x() + 1 + 2 * margin;
  const std::int64_t height = std::int64_t{high.y()} - low.y() + 1 + 2 * margin;
  if (width * height <= kMaxGridCells) return;
  // The area in metres, and the finest resolution (two significant digits,
  // rounded up) at which it fits.
  const double width_m = static_cast<double>(high.x() - low.x() + 1) * resolution + 2 * parameters_.margin;
  const double height_m = static_cast<double>(high.y() - low.y() + 1) * resolution + 2 * parameters_.margin;
  const auto fits = [&](double r) {
    return (std::ceil(width_m / r) + 2) * (std::ceil(height_m / r) + 2) <= static_cast<double>(kMaxGridCells);
  };
  double coarser = std::sqrt(width_m * height_m / static_cast<double>(kMaxGridCells));
  const double step = std::pow(10.0, std::floor(std::log10(coarser)) - 1);
  coarser = std::ceil(coarser / step) * step;
  for (int i = 0; i < 1000 && !fits(coarser); ++i) coarser += step;
  char area[96];
  std::snprintf(area, sizeof area, "%.1f m x %.1f m", width_m, height_m);
  char suggestion[32];
  std::snprintf(suggestion, sizeof suggestion, "%.2g", coarser);
  throw GridTooLarge(width, height,
                     too_many_cells_message(width, height) + " at a resolution of " + format_metres(resolution) +
                         " m (the area seen so far, " + area + ", fits at " + suggestion + " m or coarser)");
}

OccupancyGrid OccupancyGridBuilder::build() const {
  if (!touched_any_) {
    throw std::logic_error("OccupancyGridBuilder::build: no scan has touched any cell yet");
  }
  const int margin = static_cast<int>(std::ceil(parameters_.margin / parameters_.resolution));
  const Eigen::Vector2i first = touched_min_ - Eigen::Vector2i::Constant(margin);
  const Eigen::Vector2i size = touched_max_ - touched_min_ + Eigen::Vector2i::Constant(2 * margin + 1);
  OccupancyGrid grid(size.x(), size.y(), parameters_.resolution,
                     first.cast<double>() * parameters_.resolution);

  for (const auto& [key, tile] : tiles_) {
    const Eigen::Vector2i tile_corner = unpack(key) * kTileSize;
    for (int local_y = 0; local_y < kTileSize; ++local_y) {
      for (int local_x = 0; local_x < kTileSize; ++local_x) {
        const float log_odds = tile[static_cast<std::size_t>(local_y * kTileSize + local_x)];
        if (log_odds == 0.0f) continue;  // never seen (or evidence that cancelled out: p = 0.5)
        const Eigen::Vector2i cell = tile_corner + Eigen::Vector2i(local_x, local_y) - first;
        const double probability = 1.0 / (1.0 + std::exp(-static_cast<double>(log_odds)));
        if (probability >= parameters_.occupied_probability) {
          grid.set(cell.x(), cell.y(), CellState::occupied);
        } else if (probability <= parameters_.free_probability) {
          grid.set(cell.x(), cell.y(), CellState::free);
        }
      }
    }
  }
  return grid;
}

}  // namespace playerkit::grid
