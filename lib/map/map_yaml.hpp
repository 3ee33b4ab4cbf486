#pragma once
// Internal: the fields of a ROS map_server map.yaml, read and written.

#include <Eigen/Core>

#include <filesystem>
#include <string>
#include <string_view>

namespace playerkit::map {

struct MapYaml {
  std::filesystem::path image;   // resolved against the YAML file's folder when read
  double resolution = 0.0;       // metres per pixel
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // world position of the lower-left pixel's corner
  bool negate = false;
  double occupied_threshold = 0.65;
  double free_threshold = 0.196;
  // Where `image:` was written, so an unreadable image is reported there.
  int image_line = 0;
  int image_column = 0;
};

// Throws MapFileError with file:line:col for anything wrong or unsupported.
MapYaml parse_map_yaml(std::string_view text, const std::filesystem::path& yaml_file);

// The YAML text for `description` (image written as given, usually a bare file name).
std::string format_map_yaml(const MapYaml& description);

}  // namespace playerkit::map
