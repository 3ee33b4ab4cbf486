#pragma once
// A picture of a localization run: the map, the estimated (and true) paths,
// the last scan and the final pose, written as a PNG for a human to look at.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "map/map_file_error.hpp"

namespace playerkit::map {

struct PlotPath {
  std::vector<Eigen::Vector2d> points;  // world metres, in travel order
  std::array<std::uint8_t, 3> rgb{0, 0, 255};
  std::string label;  // shown in the legend unless empty
};

struct PlotOptions {
  // The longer image side is at most this. A map smaller than this is
  // enlarged by a whole number of pixels per cell (never below 1), so cells
  // stay square and crisp; a larger one is shrunk to exactly this.
  int max_side_pixels = 2000;
  // Show only the known (free or occupied) cells, the paths, scan and pose,
  // plus a small margin; otherwise the whole grid.
  bool crop_to_content = true;
};

// Writes `png` (always PNG, whatever the extension): free cells white,
// occupied black, unknown grey (also outside the grid), each path as an
// antialiased polyline in its colour, `scan_points` (world metres) as small
// red dots, `final_pose` as an arrow, and a legend of the path labels. World
// x points right and y up. Non-finite points are skipped. Throws MapFileError
// if the file cannot be written, std::invalid_argument for an empty grid or a
// non-positive max_side_pixels.
void write_trajectory_plot(const std::filesystem::path& png, const grid::OccupancyGrid& grid,
                           std::span<const PlotPath> paths,
                           std::span<const Eigen::Vector2d> scan_points,
                           const std::optional<geometry::Pose2>& final_pose,
                           const PlotOptions& options = {});

}  // namespace playerkit::map
