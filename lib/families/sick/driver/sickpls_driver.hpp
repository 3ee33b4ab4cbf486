#pragma once
// `sickpls` (manual §7.40): the laser interface from a PLS: 180 deg at 0.5 deg (1 deg by taking every second value), values in cm, no intensity.
// The driver itself is sick_laser_driver.hpp; options in
// sick_driver_settings.hpp; what differs from Player 1.5 in README.md.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec sickpls_driver_spec();

}  // namespace playerkit::drivers
