// A ROS map.yaml through map::parse_map_yaml (which reads it with the flat
// YAML reader), as load_map does before opening the image; a description it
// accepts must survive format_map_yaml and a second reading unchanged (what
// save_map writes, load_map reads back).

#include <string>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "map/map_file_error.hpp"
#include "map/map_yaml.hpp"

namespace playerkit::fuzz {
namespace map_yaml_detail {

bool same(const map::MapYaml& a, const map::MapYaml& b) {
  return a.image == b.image && a.resolution == b.resolution && a.origin == b.origin &&
         a.negate == b.negate && a.occupied_threshold == b.occupied_threshold &&
         a.free_threshold == b.free_threshold;
}

}  // namespace map_yaml_detail

int map_yaml(const std::uint8_t* data, std::size_t size) {
  const auto yaml_file = scratch_directory() / "fuzz.yaml";
  map::MapYaml description;
  try {
    description = map::parse_map_yaml(as_text({data, size}), yaml_file);
  } catch (const map::MapFileError&) {
    return 0;
  }
  const std::string written = map::format_map_yaml(description);
  map::MapYaml again;
  try {
    again = map::parse_map_yaml(written, yaml_file);
  } catch (const map::MapFileError&) {
    invariant_failed("map_yaml", "format_map_yaml wrote a description parse_map_yaml refuses");
  }
  if (!map_yaml_detail::same(description, again)) {
    invariant_failed("map_yaml", "a description changed through format_map_yaml and parse_map_yaml");
  }
  return 0;
}

}  // namespace playerkit::fuzz
