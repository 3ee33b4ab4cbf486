#pragma once
// `cmucam2` (Player 1.5 manual §7.5): a CMUcam2 colour tracker as a
// blobfinder device and its two servos as a ptz device, both on one serial
// line (`cmucam2_ptz` names the ptz one explicitly).

#include <vector>

#include "core/driver_registry.hpp"

namespace playerkit::drivers {

std::vector<core::DriverSpec> cmucam2_driver_specs();

}  // namespace playerkit::drivers
