#pragma once
// `amtecpowercube` (Player 1.5 manual §7.4): an Amtec PowerCube wrist, a pan
// and a tilt module on one serial line, as a ptz device.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec amtecpowercube_driver_spec();

}  // namespace playerkit::drivers
