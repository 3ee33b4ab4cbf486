#pragma once
// `sicklms200` (manual §7.39): the laser interface from a LMS 200: 180 deg at 0.5/1 deg or 100 deg at 0.25/0.5/1 deg, mm or cm, reflector levels.
// The driver itself is sick_laser_driver.hpp; options in
// sick_driver_settings.hpp; what differs from Player 1.5 in README.md.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec sicklms200_driver_spec();

}  // namespace playerkit::drivers
