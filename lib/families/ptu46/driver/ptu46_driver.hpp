#pragma once
// `ptu46` (Player 1.5 manual §7.32): a Directed Perception PTU-46 pan-tilt
// unit on a serial line, as a ptz device.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec ptu46_driver_spec();

}  // namespace playerkit::drivers
