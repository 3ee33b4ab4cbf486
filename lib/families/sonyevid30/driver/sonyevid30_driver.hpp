#pragma once
// `sonyevid30` (Player 1.5 manual §7.41): a Sony EVI-D30 pan-tilt-zoom
// camera on a serial line (VISCA), as a ptz device.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec sonyevid30_driver_spec();

}  // namespace playerkit::drivers
