#pragma once
// The seven Player 1.5 `rflex_*` drivers (manual §7.34): one iRobot/RWI
// robot's RFLEX controller (B21r, ATRV, ATRV-Jr, Magellan) on one serial
// line, served as up to seven devices sharing one RflexConnection
// (rflex_connection.hpp): the first device subscribed opens the line, the
// last one to leave stops and brakes the robot and closes it.
//
//   position:0 ( driver "rflex_position" rflex_serial_port "/dev/ttyR0"
//                odo_distance_conversion 103 odo_angle_conversion 35000 )
//   sonar:0    ( driver "rflex_sonar" range_distance_conversion 1.476 rflex_done 1 )

#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

// One spec per RflexRole, in its order.
std::vector<core::DriverSpec> rflex_driver_specs();

}  // namespace playerkit::drivers
