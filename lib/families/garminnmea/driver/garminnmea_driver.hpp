#pragma once
// `garminnmea` (Player 1.5 manual §7.11): a Garmin (or any NMEA 0183) GPS
// receiver on a serial line, as a gps device.

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

core::DriverSpec garminnmea_driver_spec();

}  // namespace playerkit::drivers
