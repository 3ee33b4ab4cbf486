#pragma once
// The Nomad 200 (Player 1.5 manual §7.29): `nomad` talks to Nomadic's server
// over TCP; `nomad_position` and `nomad_sonar` repackage a nomad device's
// data in the standard interfaces, as in 1.5.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec nomad_driver_spec();
core::DriverSpec nomad_position_driver_spec();
core::DriverSpec nomad_sonar_driver_spec();

}  // namespace playerkit::drivers
