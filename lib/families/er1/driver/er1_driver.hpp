#pragma once
// `er1_position` (Player 1.5 manual §7.7): the motor controller of an
// Evolution Robotics ER1 on a serial line, as a position device.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec er1_position_driver_spec();

}  // namespace playerkit::drivers
