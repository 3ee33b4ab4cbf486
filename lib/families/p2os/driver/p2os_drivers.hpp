#pragma once
// The eleven Player 1.5 `p2os_*` drivers (manual §7.30): one Pioneer
// (P2OS/AROS/AmigOS controller) on one serial line, served as up to eleven
// devices. Each device's driver holds a share of one P2osConnection
// (p2os_connection.hpp): the first device subscribed opens the line and
// runs the handshake, the last one to leave stops the motors and closes it.
//
//   position:0 ( driver "p2os_position" port "/dev/ttyUSB0" )
//   sonar:0    ( driver "p2os_sonar" )
//   power:0    ( driver "p2os_power" )

#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

// One spec per P2osRole, in its order; the names are p2os_role.hpp's.
std::vector<core::DriverSpec> p2os_driver_specs();

}  // namespace playerkit::drivers
