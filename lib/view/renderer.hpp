#pragma once
// A Frame drawn into an RGB picture, north up, centred on frame.centre:
// the map under everything (free white, occupied black, unknown grey; a
// 1 m grid on white without a map), then areas, the map's walls again (so
// cones and fans never hide them), trails, dots, ellipses, bodies, labels
// (fiducial ids), the legend at the top left and a scale bar at the bottom left.
// OpenCV stays inside renderer.cpp.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "view/shapes.hpp"

namespace playerkit::view {

struct RenderOptions {
  int width = 800;   // pixels
  int height = 800;
  double span = 12.0;  // metres across the picture's width
};

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // R, G, B per pixel, rows from the top

  [[nodiscard]] Colour at(int col, int row) const {
    const auto i = 3 * (static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(col));
    return {pixels[i], pixels[i + 1], pixels[i + 2]};
  }
};

// Continuous pixel coordinates of a world point: the centre of the picture
// is `centre`, x grows to the right and y upwards.
struct ViewTransform {
  Point centre;
  double pixels_per_metre = 1.0;
  int width = 0, height = 0;

  [[nodiscard]] Point to_pixel(const Point& world) const {
    return {0.5 * width + (world.x - centre.x) * pixels_per_metre,
            0.5 * height - (world.y - centre.y) * pixels_per_metre};
  }
};

ViewTransform view_transform(const Frame& frame, const RenderOptions& options);

// Throws std::invalid_argument for a size below 16 pixels or above 8192,
// or a span that is not a positive number.
RgbImage render(const Frame& frame, const grid::OccupancyGrid* map, const RenderOptions& options);

// Writes the picture as a PNG, atomically (a temporary renamed into place).
// Throws files::OutputError.
void write_png(const std::filesystem::path& path, const RgbImage& image);

}  // namespace playerkit::view
