#pragma once
// `flockofbirds` (Player 1.5 manual §7.10): an Ascension Flock of Birds
// 6-DOF tracker (one bird, stand-alone RS-232) as a position3d device.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec flockofbirds_driver_spec();

}  // namespace playerkit::drivers
