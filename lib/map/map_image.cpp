#include "map/map_image.hpp"

#include "files/output_file.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <system_error>
#include <string>

namespace playerkit::map {

std::optional<GreyImage> read_grey_image(const std::filesystem::path& file) {
  // OpenCV logs a warning for a missing file; callers report it better.
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return std::nullopt;
  cv::Mat image;
  try {
    image = cv::imread(file.string(), cv::IMREAD_GRAYSCALE);
  } catch (const cv::Exception&) {
    return std::nullopt;  // a corrupt file: the caller reports it with its own context
  }
  if (image.empty() || image.type() != CV_8UC1) return std::nullopt;
  GreyImage grey;
  grey.width = image.cols;
  grey.height = image.rows;
  grey.pixels.resize(static_cast<std::size_t>(image.cols) * static_cast<std::size_t>(image.rows));
  for (int row = 0; row < image.rows; ++row) {
    const std::uint8_t* source = image.ptr<std::uint8_t>(row);
    std::copy(source, source + image.cols,
              grey.pixels.begin() + static_cast<std::ptrdiff_t>(row) * image.cols);
  }
  return grey;
}

bool write_pgm(const GreyImage& image, const std::filesystem::path& file) {
  try {
    // Through a temporary renamed into place: a failed write leaves an older map whole.
    files::OutputFile output(file, {.compression = files::Compression::kNone});
    auto& out = output.stream();
    out << "P5\n# CREATOR: playerkit\n" << image.width << ' ' << image.height << "\n255\n";
    out.write(reinterpret_cast<const char*>(image.pixels.data()),
              static_cast<std::streamsize>(image.pixels.size()));
    output.commit();
    return true;
  } catch (const files::OutputError&) {
    return false;
  }
}

grid::OccupancyGrid grid_from_image(const GreyImage& image, double resolution,
                                    const Eigen::Vector2d& origin, const PixelMeaning& meaning) {
  grid::OccupancyGrid grid(image.width, image.height, resolution, origin);
  for (int image_row = 0; image_row < image.height; ++image_row) {
    const int grid_row = image.height - 1 - image_row;
    for (int col = 0; col < image.width; ++col) {
      const int value = image.pixels[static_cast<std::size_t>(image_row) * static_cast<std::size_t>(image.width) +
                                     static_cast<std::size_t>(col)];
      // Dark is occupied: occupancy is how far from white the pixel is.
      const double occupancy = (meaning.negate ? value : 255 - value) / 255.0;
      grid::CellState state = grid::CellState::unknown;
      if (occupancy > meaning.occupied_threshold) {
        state = grid::CellState::occupied;
      } else if (occupancy < meaning.free_threshold) {
        state = grid::CellState::free;
      }
      grid.set(col, grid_row, state);
    }
  }
  return grid;
}

GreyImage image_from_grid(const grid::OccupancyGrid& grid) {
  GreyImage image;
  image.width = grid.width();
  image.height = grid.height();
  image.pixels.resize(grid.cells().size());
  for (int row = 0; row < grid.height(); ++row) {
    const int image_row = grid.height() - 1 - row;
    for (int col = 0; col < grid.width(); ++col) {
      std::uint8_t value = 205;
      if (grid.at(col, row) == grid::CellState::free) value = 254;
      if (grid.at(col, row) == grid::CellState::occupied) value = 0;
      image.pixels[static_cast<std::size_t>(image_row) * static_cast<std::size_t>(grid.width()) +
                   static_cast<std::size_t>(col)] = value;
    }
  }
  return image;
}

}  // namespace playerkit::map
