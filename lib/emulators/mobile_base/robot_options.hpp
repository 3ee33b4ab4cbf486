#pragma once
// The emulator options every mobile base takes, so `player-drivers emulate
// p2os`, `rflex`, `khepera`... start and err the same way: where the robot
// stands and how wrong its odometry is.
//
//   kind.options = mobile_base::robot_option_docs();
//   kind.options.push_back({"model", "b21r", "..."});
//   const RobotBodyOptions body = mobile_base::read_robot_options(options);

#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "emulators/emulator_kind.hpp"
#include "emulators/mobile_base/odometry_error.hpp"

namespace playerkit::emulators {
class EmulatorOptionReader;
}

namespace playerkit::emulators::mobile_base {

struct RobotBodyOptions {
  geometry::Pose2 initial_pose;  // world frame, metres and radians
  OdometryError odometry_error;
};

// pose, odometry_scale, rotation_scale, drift, seed.
[[nodiscard]] std::vector<EmulatorOptionDoc> robot_option_docs();

// Reads them (each with its range); throws std::invalid_argument naming the
// kind and the option for a bad value.
[[nodiscard]] RobotBodyOptions read_robot_options(const EmulatorOptionReader& options);

}  // namespace playerkit::emulators::mobile_base
