#pragma once
// Builds an occupancy grid from laser scans taken at known poses: the
// log-odds update of Probabilistic Robotics (Thrun, Burgard & Fox), ch. 9,
// with an inverse sensor model of "free along the beam, occupied at its end".
// The area grows as scans arrive; only the parts seen take memory.

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace playerkit::grid {

struct OccupancyMappingParameters {
  double resolution = 0.05;              // metres per cell
  double max_usable_range = 30.0;        // longer readings only clear free space up to this
  // How far a no-return (max-range) reading clears. 0, the default: not at
  // all. Indoors a laser returns nothing from glass, black or steeply struck
  // surfaces, not only from empty space; on the Radish Freiburg 079 log such
  // readings (2% of all) cleared whole stretches of wall and made amcl lose
  // track (docs/amcl.md).
  double no_return_clear_range = 0.0;
  double hit_log_odds = 0.85;            // added to a cell a beam ends in
  double miss_log_odds = -0.4;           // added to cells a beam passes through
  double occupied_probability = 0.65;    // build(): p >= this -> occupied
  double free_probability = 0.196;       // build(): p <= this -> free (else unknown)
  double margin = 1.0;                   // metres of unknown border around what was seen
};

class OccupancyGridBuilder {
 public:
  // Throws std::invalid_argument for a non-positive resolution or usable
  // range, a negative margin, or probabilities outside (0, 1).
  explicit OccupancyGridBuilder(OccupancyMappingParameters parameters = {});

  // ranges[i] is at bearing angle_min + i * angle_increment in the laser
  // frame; `laser_pose` is the laser's pose in the world. Readings >=
  // max_range are "no return": they mark no hit and clear cells up to
  // min(max_range, max_usable_range, no_return_clear_range). Readings <= 0 or
  // NaN are ignored.
  // Within one scan each cell is updated at most once, and a cell some beam
  // ends in counts as a hit even if other beams pass through it. Throws
  // GridTooLarge, before taking any memory for the scan, when the map would
  // pass kMaxGridCells (its message names the resolution that would fit).
  void add_scan(const geometry::Pose2& laser_pose, std::span<const double> ranges, double angle_min,
                double angle_increment, double max_range);

  std::size_t scan_count() const { return scan_count_; }

  // Bounds are every cell touched plus `margin`; throws std::logic_error if
  // no cell has been touched yet.
  OccupancyGrid build() const;

  const OccupancyMappingParameters& parameters() const { return parameters_; }

 private:
  static constexpr int kTileShift = 6;  // 64 x 64 cells per tile
  static constexpr int kTileSize = 1 << kTileShift;
  using Tile = std::array<float, kTileSize * kTileSize>;  // log odds, 0 = never seen

  void update_cell(const Eigen::Vector2i& cell, double log_odds_change);
  // Throws GridTooLarge when the map, with a scan spanning these cells, would
  // pass kMaxGridCells.
  void check_size(const Eigen::Vector2i& scan_low, const Eigen::Vector2i& scan_high) const;

  OccupancyMappingParameters parameters_;
  std::unordered_map<std::uint64_t, Tile> tiles_;
  std::size_t scan_count_ = 0;
  bool touched_any_ = false;
  Eigen::Vector2i touched_min_ = Eigen::Vector2i::Zero();
  Eigen::Vector2i touched_max_ = Eigen::Vector2i::Zero();
  // Consecutive cells of a beam are mostly in the same tile.
  Tile* last_tile_ = nullptr;
  std::uint64_t last_tile_key_ = 0;
  // Per-scan scratch, kept between scans to reuse its memory: one mark per
  // cell of the scan's bounding box, and the cells marked.
  std::vector<std::uint8_t> scan_marks_;
  std::vector<Eigen::Vector2i> scan_cells_;
};

}  // namespace playerkit::grid
