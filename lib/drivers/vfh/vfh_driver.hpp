#pragma once
// `vfh` (Player 1.5 manual §7.45): a position device that drives another
// position device to goals (position mode) or at given speeds (velocity
// mode) around what a laser sees, with the Vector Field Histogram
// (lib/algorithms/vfh), e.g.
//
//   position:1 ( driver "vfh" position_index 0 laser_index 0 safety_dist 0.1 )
//
// Goals are in the underlying device's odometric frame; the data it
// publishes is that odometry, its stall flag also set once vfh gives a goal
// up (turning a turn and a half without getting nearer) until the next command.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec vfh_driver_spec();

}  // namespace playerkit::drivers
