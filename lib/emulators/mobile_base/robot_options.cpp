#include "emulators/mobile_base/robot_options.hpp"

#include <numbers>

#include "emulators/emulator_option_reader.hpp"

namespace playerkit::emulators::mobile_base {

std::vector<EmulatorOptionDoc> robot_option_docs() {
  return {
      {"pose", "0,0,0", "where it starts in the map: x,y,yaw in m, m, deg"},
      {"odometry_scale", "0", "odometry error: measured distance = true x (1 + this)"},
      {"rotation_scale", "0", "odometry error: measured rotation = true x (1 + this)"},
      {"drift", "0", "odometry error: heading drift, deg per m driven"},
      {"seed", "1", "seed of the odometry noise"},
  };
}

RobotBodyOptions read_robot_options(const EmulatorOptionReader& options) {
  RobotBodyOptions body;
  body.initial_pose = options.pose("pose", {});
  body.odometry_error.translation_scale = options.number("odometry_scale", 0.0, -0.5, 0.5);
  body.odometry_error.rotation_scale = options.number("rotation_scale", 0.0, -0.5, 0.5);
  body.odometry_error.heading_drift_per_metre = options.number("drift", 0.0, -90.0, 90.0) * std::numbers::pi / 180.0;
  body.odometry_error.seed = static_cast<std::uint64_t>(options.integer("seed", 1, 0, 2147483647));
  return body;
}

}  // namespace playerkit::emulators::mobile_base
