#pragma once
// `wavefront` (Player 1.5 manual §7.47): a position device that takes a goal
// on the map as a position command, plans a path to it from where the
// localize device says the robot is (lib/algorithms/wavefront), and hands
// the path's waypoints one at a time, in the odometric frame, to a position
// device that drives to positions (vfh), e.g.
//
//   position:2 ( driver "wavefront" position_index 1 localize_index 0
//                map_filename "cave.png" map_scale 0.03 robot_radius 0.25 )
//
// Its data is the localized pose, the driven device's speeds and a stall
// flag that is 1 while it is not driving: before a goal, at the goal, after
// a goal it refused (inside an obstacle, unreachable: one log line) or gave
// up on.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec wavefront_driver_spec();

}  // namespace playerkit::drivers
