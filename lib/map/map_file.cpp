#include "map/map_file.hpp"

#include "map/map_image.hpp"
#include "map/map_yaml.hpp"

#include "files/output_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

namespace playerkit::map {
namespace {

bool is_yaml(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".yaml" || extension == ".yml";
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw MapFileError(file, "cannot open file");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw MapFileError(file, "cannot read file");
  return text;
}

grid::OccupancyGrid load_yaml_map(const std::filesystem::path& yaml_file) {
  const MapYaml description = parse_map_yaml(read_text(yaml_file), yaml_file);
  const std::optional<GreyImage> image = read_grey_image(description.image);
  if (!image) {
    throw MapFileError(yaml_file, description.image_line, description.image_column,
                       std::string("cannot read image '") + description.image.string() + "'");
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
  if (!std::filesystem::exists(image_file)) throw MapFileError(image_file, "no such file");
  const std::optional<GreyImage> image = read_grey_image(image_file);
  if (!image) throw MapFileError(image_file, "cannot read as an image");
  // Player 1.5 (manual 7.3): the world origin is the centre of the map.
  const Eigen::Vector2d origin(-0.5 * image->width * resolution, -0.5 * image->height * resolution);
  return grid_from_image(*image, resolution, origin,
                         {options.negate, options.occupied_threshold, options.free_threshold});
}

}  // namespace

grid::OccupancyGrid load_map(const std::filesystem::path& file, const MapLoadOptions& options) {
  return is_yaml(file) ? load_yaml_map(file) : load_image_map(file, options);
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
