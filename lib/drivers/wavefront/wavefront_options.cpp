#include "drivers/wavefront/wavefront_options.hpp"

#include <algorithm>
#include <numbers>
#include <string>

#include "config/errors.hpp"
#include "core/option_reader.hpp"
#include "map/map_file.hpp"
#include "map/map_file_error.hpp"

namespace playerkit::drivers::wavefront_driver {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

const core::OptionSchema& wavefront_option_schema() {
  using core::OptionSpec;
  using core::OptionType;
  static const core::OptionSchema schema{
      OptionSpec::integer("position_index", 0, 0, 65535).doc("the position device to hand waypoints to (vfh)"),
      OptionSpec::integer("localize_index", 0, 0, 65535).doc("the localize device giving the pose on the map (amcl)"),
      OptionSpec::filename("map_filename", "").allow_empty().aliases({"map_file"}).doc("the map image (or a ROS .yaml), as amcl reads it"),
      OptionSpec::length("map_scale", 0.05, 0.0001, 100.0).unit("m").doc("metres per pixel of the image"),
      OptionSpec::integer("map_negate", 0, 0, 1).doc("1: white is occupied"),
      OptionSpec::tuple("map_origin", {OptionType::length, OptionType::length}, {0, 0})
          .shown_default("(centred)")
          .unit("m m")
          .doc("where the image's bottom-left corner lies; [0 0] for a Stage 1.3 world"),
      OptionSpec::filename("cspace_filename", "").allow_empty().doc("1.5's precomputed c-space: read as a name only, the c-space is computed exactly"),
      OptionSpec::length("robot_radius", 0.15, 0.001, 10.0).unit("m").doc("the robot's radius"),
      OptionSpec::length("safety_dist", 0.15, 0.0, 10.0).shown_default("robot_radius").unit("m").doc("clearance kept beyond the radius"),
      OptionSpec::length("max_radius", 1.0, 0.0, 100.0).unit("m").doc("1.5's c-space cut-off; distances are exact here"),
      OptionSpec::number("dist_penalty", 1.0, 0.0, 1000.0).doc("extra cost of passing near walls"),
      OptionSpec::length("distance_epsilon", 0.45, 0.001, 100.0)
          .aliases({"dist_epsilon", "dist_eps"})
          .shown_default("3 x robot_radius")
          .unit("m")
          .doc("near enough to a waypoint or the goal"),
      OptionSpec::angle("angle_epsilon", 10 * kDegree, 0.001 * kDegree, 180 * kDegree)
          .aliases({"ang_eps"})
          .unit("deg")
          .doc("facing the goal's heading closely enough"),
      OptionSpec::length("replan_distance", 1.0, 0.05, 100.0).unit("m").doc("off the path by this much: plan again (beyond 1.5)"),
  };
  return schema;
}

WavefrontOptions read_wavefront_options(const config::Section& section) {
  const core::OptionReader options(section, "wavefront", wavefront_option_schema());
  WavefrontOptions read;
  read.position_index = options.integer("position_index");
  read.localize_index = options.integer("localize_index");
  read.planner.robot_radius = options.length("robot_radius");
  read.planner.safety_distance = options.has("safety_dist") ? options.length("safety_dist") : read.planner.robot_radius;
  read.planner.distance_penalty = options.number("dist_penalty");
  read.follower.distance_epsilon =
      options.has("distance_epsilon") ? options.length("distance_epsilon") : 3 * read.planner.robot_radius;
  read.follower.angle_epsilon = options.angle("angle_epsilon");
  read.follower.stray_distance = options.length("replan_distance");

  const std::string file = options.text("map_filename");
  if (file.empty()) options.fail({"map_filename", "map_file"}, "no map: give map_filename \"map.png\" and map_scale");
  map::MapLoadOptions load;
  load.resolution = options.length("map_scale");
  load.negate = options.integer("map_negate") != 0;
  if (options.has("map_origin")) load.origin = Eigen::Vector2d(options.element("map_origin", 0), options.element("map_origin", 1));
  try {
    read.map = std::make_shared<grid::OccupancyGrid>(map::load_map(file, load));
  } catch (const map::MapFileError& e) {
    options.fail({"map_filename", "map_file"}, std::string("cannot load the map: ") + e.what());
  }
  const auto cells = read.map->cells();
  if (std::none_of(cells.begin(), cells.end(), [](grid::CellState s) { return s == grid::CellState::free; })) {
    options.fail({"map_filename", "map_file"}, "has no free cells (wrong map_negate?)");
  }
  return read;
}

}  // namespace playerkit::drivers::wavefront_driver
