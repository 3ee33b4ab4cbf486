#include "drivers/vfh/vfh_options.hpp"

#include <numbers>
#include <stdexcept>

#include "core/option_reader.hpp"

namespace playerkit::drivers::vfh_driver {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
// max_speed above this is the manual's millimetres a second ("integer 200");
// below, the metres a second 1.5's source and its shipped files used.
constexpr double kLargestSpeedInMetres = 10.0;

}  // namespace

const core::OptionSchema& vfh_option_schema() {
  using core::OptionSpec;
  static const core::OptionSchema schema{
      OptionSpec::integer("position_index", 0, 0, 65535).doc("the position device to drive, on the same port"),
      OptionSpec::integer("laser_index", 0, 0, 65535).doc("the laser to steer by"),
      OptionSpec::integer("truth_index", -1, -1, 65535).doc("1.5's truth device for the pose: not supported, -1 only"),
      OptionSpec::length("cell_size", 0.1, 0.01, 1.0).unit("m").doc("histogram grid cell"),
      OptionSpec::integer("window_diameter", 61, 3, 401).unit("cells").doc("cells across the window around the robot"),
      OptionSpec::integer("sector_angle", 5, 1, 90).unit("deg").doc("histogram sector; divides 360"),
      OptionSpec::length("robot_radius", 0.25, 0.0, 5.0).unit("m").doc("the robot's radius"),
      OptionSpec::length("safety_dist", 0.1, 0.0, 5.0).unit("m").doc("distance kept beyond the radius"),
      OptionSpec::number("max_speed", 0.2, 0.0, 10000.0)
          .unit("m/s")
          .doc("top speed; values above 10 are the manual's mm/s (200 = 0.2 m/s)"),
      OptionSpec::angle("max_turnrate", 40 * kDegree, 0.01 * kDegree, 360 * kDegree).unit("deg/s").doc("top turn rate"),
      OptionSpec::angle("min_turnrate", 10 * kDegree, 0.0, 360 * kDegree).unit("deg/s").doc("slowest turn in place"),
      OptionSpec::number("free_space_cutoff", 2.0e6, 0.0, 1e12).doc("histogram value below which a sector is free"),
      OptionSpec::number("obs_cutoff", 2.0e6, 0.0, 1e12)
          .shown_default("free_space_cutoff")
          .doc("above which a sector is blocked (between the two: as it was)"),
      OptionSpec::number("weight_desired_dir", 5.0, 0.0, 1e6).doc("pull towards the goal's direction"),
      OptionSpec::number("weight_current_dir", 3.0, 0.0, 1e6).doc("pull towards the direction taken last"),
      OptionSpec::length("distance_epsilon", 0.5, 0.001, 100.0).aliases({"dist_eps"}).unit("m").doc("near enough to the goal"),
      OptionSpec::angle("angle_epsilon", 10 * kDegree, 0.001 * kDegree, 180 * kDegree)
          .aliases({"ang_eps"})
          .unit("deg")
          .doc("facing the goal's heading closely enough"),
  };
  return schema;
}

VfhOptions read_vfh_options(const config::Section& section) {
  const core::OptionReader options(section, "vfh", vfh_option_schema());
  VfhOptions read;
  read.position_index = options.integer("position_index");
  read.laser_index = options.integer("laser_index");
  if (options.integer("truth_index") >= 0) {
    options.fail({"truth_index"}, "a truth device for the pose is not supported: vfh steers by the odometry "
                                  "of its position device, in whose frame goals are given");
  }
  vfh::VfhParameters& p = read.navigator.planner;
  p.cell_size = options.length("cell_size");
  p.window_diameter = options.integer("window_diameter");
  p.sector_angle = options.integer("sector_angle");
  p.robot_radius = options.length("robot_radius");
  p.safety_distance = options.length("safety_dist");
  const double max_speed = options.number("max_speed");
  p.max_speed = max_speed > kLargestSpeedInMetres ? max_speed / 1000.0 : max_speed;
  p.max_turn_rate = options.angle("max_turnrate");
  p.min_turn_rate = options.angle("min_turnrate");
  p.free_space_cutoff = options.number("free_space_cutoff");
  p.obstacle_cutoff = options.has("obs_cutoff") ? options.number("obs_cutoff") : p.free_space_cutoff;
  p.weight_desired_direction = options.number("weight_desired_dir");
  p.weight_current_direction = options.number("weight_current_dir");
  read.navigator.distance_epsilon = options.length("distance_epsilon");
  read.navigator.angle_epsilon = options.angle("angle_epsilon");
  if (360 % p.sector_angle != 0) options.fail({"sector_angle"}, "must divide 360");
  if (p.min_turn_rate > p.max_turn_rate) options.fail({"min_turnrate"}, "must not exceed max_turnrate");
  if (p.obstacle_cutoff < p.free_space_cutoff) options.fail({"obs_cutoff"}, "must not be below free_space_cutoff");
  return read;
}

}  // namespace playerkit::drivers::vfh_driver
