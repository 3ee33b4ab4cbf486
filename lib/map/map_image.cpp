#include "map/map_image.hpp"

#include "files/output_file.hpp"

#include "image/png.hpp"
#include "image/pnm.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>
#include <string>

namespace playerkit::map {

std::optional<GreyImage> read_grey_image(const std::filesystem::path& file, std::string* why) {
  const auto fail = [why](std::string reason) -> std::optional<GreyImage> {
    if (why != nullptr) *why = std::move(reason);
    return std::nullopt;
  };
  std::error_code error;
  if (!std::filesystem::exists(file, error)) return fail("no such file");
  if (!std::filesystem::is_regular_file(file, error)) return fail("not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return fail("cannot read it");
  std::ifstream in(file, std::ios::binary);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!in || in.gcount() != static_cast<std::streamsize>(bytes.size())) return fail("cannot read it");
  image::Decoded decoded;
  if (image::is_png(bytes)) {
    decoded = image::decode_png(bytes);
  } else if (image::is_pnm(bytes)) {
    decoded = image::decode_pnm(bytes);
  } else {
    return fail("not a PNG, PGM, PPM or PBM image (convert other formats to PNG)");
  }
  if (!decoded.ok()) return fail(decoded.error);
  return std::move(decoded.image);
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
