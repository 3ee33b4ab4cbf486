#pragma once
// Every driver player-drivers knows: the built-in ones, the plugins' (-d),
// and those a hardware family brings beyond the built-in list (a family made
// in a test).

#include <string>
#include <vector>

#include "core/driver_registry.hpp"
#include "core/logger.hpp"
#include "families/family_registry.hpp"

namespace playerkit::player_drivers {

// The drivers the families bring, each marked with its family's name.
std::vector<core::DriverSpec> drivers_brought_by(const families::FamilyRegistry& families);

// Throws core::PluginError.
core::DriverRegistry known_drivers(const std::vector<std::string>& plugins, const families::FamilyRegistry& families,
                                   core::Logger& logger);

}  // namespace playerkit::player_drivers
