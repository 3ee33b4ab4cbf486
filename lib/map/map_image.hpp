#pragma once
// Internal: 8-bit grey images and their meaning as occupancy, both ways.

#include "algorithms/grid/occupancy_grid.hpp"
#include "image/grey_image.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace playerkit::map {

using GreyImage = image::GreyImage;  // row 0 at the TOP, as in the file

// A PNG or PNM file (lib/image); colour is converted to grey and deeper
// images to 8 bits. nullopt if the file cannot be read as such an image,
// with the reason in `why` when given.
std::optional<GreyImage> read_grey_image(const std::filesystem::path& file, std::string* why = nullptr);

// Binary PGM (P5). Returns false if the file cannot be written.
bool write_pgm(const GreyImage& image, const std::filesystem::path& file);

struct PixelMeaning {
  bool negate = false;             // occupancy = v/255 instead of (255 - v)/255
  double occupied_threshold = 0.65;  // occupancy above this: occupied
  double free_threshold = 0.196;     // below this: free; between: unknown
};

// Flips rows: the image's bottom row becomes grid row 0.
grid::OccupancyGrid grid_from_image(const GreyImage& image, double resolution,
                                    const Eigen::Vector2d& origin, const PixelMeaning& meaning);

// map_saver's pixels: 254 free, 0 occupied, 205 unknown; top row = last grid row.
GreyImage image_from_grid(const grid::OccupancyGrid& grid);

}  // namespace playerkit::map
