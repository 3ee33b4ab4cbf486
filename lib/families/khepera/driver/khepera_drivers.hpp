#pragma once
// Player 1.5's khepera_position and khepera_ir (manual §7.21): one K-Team
// Khepera on one serial line, served as two devices sharing one
// KheperaConnection (khepera_connection.hpp).
//
//   position:0 ( driver "khepera_position" port "/dev/ttyUSB0" )
//   ir:0       ( driver "khepera_ir" )

#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

std::vector<core::DriverSpec> khepera_driver_specs();

}  // namespace playerkit::drivers
