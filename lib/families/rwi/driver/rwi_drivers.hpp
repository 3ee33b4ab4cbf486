#pragma once
// `rwi_position`, `rwi_sonar`, `rwi_laser`, `rwi_bumper`, `rwi_power`
// (Player 1.5 manual §7.35): registered so that a configuration naming them
// is refused with the reason and the rflex_* section to use instead.

#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

std::vector<core::DriverSpec> rwi_driver_specs();

}  // namespace playerkit::drivers
