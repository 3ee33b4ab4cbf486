#pragma once
// What `player-drivers info` shows for sicklms200 and sickpls: the options
// (their schema, sick_driver_settings.hpp), requests, and a section to paste.

#include "core/driver_registry.hpp"
#include "families/sick/protocol/codes.hpp"

namespace playerkit::drivers::sick_laser {

core::DriverDoc sick_driver_doc(hardware::sick::Model model);

}  // namespace playerkit::drivers::sick_laser
