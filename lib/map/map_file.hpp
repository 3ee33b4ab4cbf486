#pragma once
// Loading and saving occupancy maps: Player 1.5 map images (amcl's map_file,
// map_scale, map_negate) and ROS map_server YAML + image pairs.

#include <Eigen/Core>

#include "algorithms/grid/occupancy_grid.hpp"
#include "map/map_file_error.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>

namespace playerkit::map {

// A ROS map description is a few lines (~150 bytes); a larger .yaml is not
// read. Images may have at most grid::kMaxGridCells pixels, checked from a
// PNM or PNG header before decoding (docs/limits.md).
inline constexpr std::size_t kMaxMapYamlBytes = std::size_t{64} << 10;

struct MapLoadOptions {
  std::optional<double> resolution;   // m/pixel; required for a plain image (Player's map_scale), ignored for YAML
  bool negate = false;                 // Player's map_negate / ROS negate (for images; YAML has its own key)
  // Where a plain image's bottom-left corner lies in the world (m); nullopt:
  // the image centred on the world origin, as Player 1.5's map driver placed
  // it. A Stage 1.3 world's bitmap without a pose lies at (0, 0).
  std::optional<Eigen::Vector2d> origin{};
  double occupied_threshold = 0.65;   // occupancy probability above which a pixel is occupied
  double free_threshold = 0.196;      // below which it is free; between -> unknown
};

// A `.yaml`/`.yml` file is a ROS map description (its own resolution,
// origin, negate and thresholds; `options` are ignored). Anything else is an
// image read by OpenCV (PGM, PNM, PNG, ...; colour becomes grey) with Player
// 1.5's meaning: occupancy (255 - v) / 255 (v / 255 negated), the map centred
// on the world origin unless `options.origin` places it. Throws MapFileError.
grid::OccupancyGrid load_map(const std::filesystem::path& file, const MapLoadOptions& options = {});

// Writes a binary PGM the way map_saver does (254 free, 0 occupied, 205
// unknown) and beside it `<stem>.yaml` naming it, so load_map(yaml) gives
// back the same grid. Throws MapFileError.
void save_map(const grid::OccupancyGrid& grid, const std::filesystem::path& pgm_file);

}  // namespace playerkit::map
