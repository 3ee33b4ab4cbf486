#include "map/map_file.hpp"

#include "map/image_header.hpp"
#include "map/map_image.hpp"
#include "map/map_yaml.hpp"

#include "files/output_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>

#include "text/printable.hpp"

namespace playerkit::map {
namespace {

bool is_yaml(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".yaml" || extension == ".yml";
}

// A map file must be a regular file: a directory or a device (/dev/zero)
// is refused before it is read.
void require_regular_file(const std::filesystem::path& file) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (!std::filesystem::exists(status)) throw MapFileError(file, "no such file");
  if (std::filesystem::is_directory(status)) throw MapFileError(file, "it is a directory, not a file");
  if (!std::filesystem::is_regular_file(status)) {
    throw MapFileError(file, "it is not a regular file (a device, a pipe or a socket)");
  }
}

std::string read_text(const std::filesystem::path& file) {
  require_regular_file(file);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw MapFileError(file, "cannot open file");
  std::string text;
  char block[4096];
  while (in.read(block, sizeof block) || in.gcount() > 0) {
    text.append(block, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxMapYamlBytes) {
      throw MapFileError(file, "larger than " + std::to_string(kMaxMapYamlBytes) + " bytes: not a map description");
    }
  }
  if (in.bad()) throw MapFileError(file, "cannot read file");
  return text;
}

// Refuses an image whose header declares more pixels than a grid may have,
// before it is decoded (decoding takes a byte per pixel at least).
void check_image_size(const std::filesystem::path& image) {
  if (const auto size = image_size_from_header(image)) {
    if (size->width * size->height > grid::kMaxGridCells) {
      throw MapFileError(image, grid::too_many_cells_message(size->width, size->height));
    }
  }
}

grid::OccupancyGrid load_yaml_map(const std::filesystem::path& yaml_file) {
  const MapYaml description = parse_map_yaml(read_text(yaml_file), yaml_file);
  check_image_size(description.image);
  std::string why;
  const std::optional<GreyImage> image = read_grey_image(description.image, &why);
  if (!image) {
    throw MapFileError(yaml_file, description.image_line, description.image_column,
                       std::string("cannot read image '") + text::excerpt(description.image.string()) + "': " + why);
  }
  return grid_from_image(*image, description.resolution, description.origin,
                         {description.negate, description.occupied_threshold,
                          description.free_threshold});
}

grid::OccupancyGrid load_image_map(const std::filesystem::path& image_file,
                                   const MapLoadOptions& options) {
  if (!options.resolution) {
    throw MapFileError(image_file, "a plain map image needs a resolution in m/pixel (Player's map_scale)");
  }
  const double resolution = *options.resolution;
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw MapFileError(image_file, "the resolution must be a positive number of m/pixel");
  }
  require_regular_file(image_file);
  check_image_size(image_file);
  std::string why;
  const std::optional<GreyImage> image = read_grey_image(image_file, &why);
  if (!image) throw MapFileError(image_file, "cannot read as an image: " + why);
  if (options.origin && !options.origin->allFinite()) {
    throw MapFileError(image_file, "the map's origin must be finite");
  }
  // Player 1.5 (manual 7.3): the world origin is the centre of the map.
  const Eigen::Vector2d origin = options.origin.value_or(
      Eigen::Vector2d(-0.5 * image->width * resolution, -0.5 * image->height * resolution));
  return grid_from_image(*image, resolution, origin,
                         {options.negate, options.occupied_threshold, options.free_threshold});
}

}  // namespace

grid::OccupancyGrid load_map(const std::filesystem::path& file, const MapLoadOptions& options) {
  try {
    return is_yaml(file) ? load_yaml_map(file) : load_image_map(file, options);
  } catch (const grid::GridTooLarge& error) {  // an image whose header was not read here
    throw MapFileError(file, error.what());
  }
}

void save_map(const grid::OccupancyGrid& grid, const std::filesystem::path& pgm_file) {
  if (grid.empty()) throw MapFileError(pgm_file, "cannot save an empty map");
  if (is_yaml(pgm_file)) throw MapFileError(pgm_file, "the image file must not be the .yaml file");
  if (!write_pgm(image_from_grid(grid), pgm_file)) throw MapFileError(pgm_file, "cannot write file");

  MapYaml description;
  description.image = pgm_file.filename();
  description.resolution = grid.resolution();
  description.origin = grid.origin();
  std::filesystem::path yaml_file = pgm_file;
  yaml_file.replace_extension(".yaml");
  try {
    files::OutputFile out(yaml_file, {.compression = files::Compression::kNone});
    out.stream() << format_map_yaml(description);
    out.commit();
  } catch (const files::OutputError&) {
    throw MapFileError(yaml_file, "cannot write file");
  }
}

}  // namespace playerkit::map
