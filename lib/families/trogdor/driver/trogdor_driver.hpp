#pragma once
// `trogdor` (Player 1.5 manual §7.42): the Botrics O-Bot ("Trogdor") on a
// serial line, as a position device.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec trogdor_driver_spec();

}  // namespace playerkit::drivers
