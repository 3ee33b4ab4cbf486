#pragma once
// The three Player 1.5 `reb_*` drivers (manual §7.33): a UMass UBot (K-Team
// Kameleon 376SBC with the Robotics Extension Board, LPRSerCom firmware) on
// one serial line, served as up to three devices sharing one RebConnection:
// the first device subscribed opens the line, the last one to leave stops
// the motors, switches the IR emitters off and closes it.
//
//   position:0 ( driver "reb_position" port "/dev/ttySA1" subclass "slow" )
//   ir:0       ( driver "reb_ir" )
//   power:0    ( driver "reb_power" )

#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

std::vector<core::DriverSpec> reb_driver_specs();

}  // namespace playerkit::drivers
