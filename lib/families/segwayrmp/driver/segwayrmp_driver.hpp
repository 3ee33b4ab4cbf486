#pragma once
// The Segway RMP (Player 1.5 manual §7.37): `segwayrmp` (position,
// position3d, power), and 1.5's registered names `rmpposition` (position,
// position3d) and `rmppower` (power), all devices of one robot on one CAN bus.

#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

std::vector<core::DriverSpec> segwayrmp_driver_specs();

}  // namespace playerkit::drivers
